//! Which states a model integrates: the core ones and the optional extras.

use serde::Serialize;

/// Optional states a scene may ask for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct Extras {
    /// The heading $\psi$ of the triad ($\dot\psi = \Omega$).
    pub heading: bool,
    /// The centre of mass in the plane (x, y); needs the heading.
    pub path: bool,
    /// The face angle $\phi$ of a mark on the disk ($\dot\phi = \omega_1 + \Omega\cos\alpha$).
    pub face: bool,
}

/// The index of every state of a model. The `core` states come first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Layout {
    /// Number of core states (4 rolling, 3 frictionless, 1 adiabatic).
    pub core: usize,
    /// Index of the heading.
    pub heading: Option<usize>,
    /// Index of x (y follows it).
    pub path: Option<usize>,
    /// Index of the face angle.
    pub face: Option<usize>,
    /// Total number of states.
    pub len: usize,
}

impl Layout {
    /// The layout for `core` core states plus `extras` (the path brings the heading with it,
    /// since the direction of travel depends on it).
    pub fn new(core: usize, extras: Extras) -> Self {
        let mut len = core;
        let mut next = |n: usize, on: bool| {
            on.then(|| {
                len += n;
                len - n
            })
        };
        let heading = next(1, extras.heading || extras.path);
        let path = next(2, extras.path);
        let face = next(1, extras.face);
        Self {
            core,
            heading,
            path,
            face,
            len,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extras_are_appended_after_the_core() {
        let l = Layout::new(4, Extras::default());
        assert_eq!(l.len, 4);
        let l = Layout::new(
            4,
            Extras {
                path: true,
                face: true,
                heading: false,
            },
        );
        assert_eq!(
            (l.heading, l.path, l.face, l.len),
            (Some(4), Some(5), Some(7), 8)
        );
        let l = Layout::new(
            3,
            Extras {
                face: true,
                ..Extras::default()
            },
        );
        assert_eq!((l.heading, l.path, l.face, l.len), (None, None, Some(3), 4));
    }
}
