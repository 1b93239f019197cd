//! Placeholder: the independent lab-frame Newton-Euler model (issue 4) lands here.
