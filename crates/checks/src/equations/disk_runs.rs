//! The errors of an approximation measured over several disks ($k$) and dissipation laws
//! ($P = -\epsilon m a g\,\Omega^\beta$, eq 75), kept per run so that its verdict can be
//! recomputed under each choice the paper leaves open: the disk's $k$ (sec. 11 names none; the
//! toy is near $k = 1/2$, a uniform disk has $k = 1/4$) and the form of the dissipation ($\beta$,
//! which sec. 11 fits to the data rather than fixes). As read, the error at each small
//! parameter is the worst over every run; each alternative takes one $k$ or one $\beta$ alone.
//! A verdict the same under all is robust to them.

use crate::finding::Finding;
use crate::robustness::Alternative;

/// Errors at each small parameter, per run `(k, beta)`; `beta` is `None` for a check without
/// dissipation.
#[derive(Debug, Clone, Default)]
pub(crate) struct DiskRuns {
    runs: Vec<(f64, Option<f64>, Vec<f64>)>,
}

impl DiskRuns {
    /// Records the error `error` of run `(k, beta)` at the `i`-th of `n` small parameters
    /// (a NaN as an infinite error: a run that could not be measured counts against the claim).
    pub(crate) fn add(&mut self, k: f64, beta: Option<f64>, n: usize, i: usize, error: f64) {
        let error = if error.is_nan() { f64::INFINITY } else { error };
        let at = match self.runs.iter().position(|r| r.0 == k && r.1 == beta) {
            Some(at) => at,
            None => {
                self.runs.push((k, beta, vec![0.0; n]));
                self.runs.len() - 1
            }
        };
        let errors = &mut self.runs[at].2;
        errors[i] = errors[i].max(error);
    }

    /// The worst error at each of `n` small parameters over the runs that `keep`.
    fn worst(&self, n: usize, keep: impl Fn(f64, Option<f64>) -> bool) -> Vec<f64> {
        let mut out = vec![0.0f64; n];
        for (k, beta, errors) in &self.runs {
            if keep(*k, *beta) {
                for (o, e) in out.iter_mut().zip(errors) {
                    *o = o.max(*e);
                }
            }
        }
        out
    }

    /// The worst error at each of `n` small parameters over every run: the errors as read.
    pub(crate) fn all(&self, n: usize) -> Vec<f64> {
        self.worst(n, |_, _| true)
    }

    /// The verdict as read (every run) and under each $k$ alone and each $\beta$ alone (when
    /// there are two or more of it), each judged by [`Finding::from_order`] at `small` against
    /// `claimed_order`, its fitted order as the reference.
    pub(crate) fn alternatives(&self, small: &[f64], claimed_order: f64) -> Vec<Alternative> {
        let judge = |errors: Vec<f64>| {
            let f = Finding::from_order("", small, &errors, claimed_order);
            (f.reference, f.verdict)
        };
        let mut ks: Vec<f64> = self.runs.iter().map(|r| r.0).collect();
        let mut betas: Vec<f64> = self.runs.iter().filter_map(|r| r.1).collect();
        for v in [&mut ks, &mut betas] {
            v.sort_by(f64::total_cmp);
            v.dedup();
        }
        let list = |v: &[f64]| {
            v.iter()
                .map(|x| format!("{x}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let n = small.len();
        let (reference, verdict) = judge(self.all(n));
        let mut out = vec![Alternative::new(
            "k of the disk",
            if betas.is_empty() {
                format!("as read: the worst over $k = {}$", list(&ks))
            } else {
                format!(
                    "as read: the worst over $k = {}$ and $\\beta = {}$",
                    list(&ks),
                    list(&betas)
                )
            },
            reference,
            verdict,
        )];
        if ks.len() > 1 {
            for &k in &ks {
                let (reference, verdict) = judge(self.worst(n, |kk, _| kk == k));
                out.push(Alternative::new(
                    "k of the disk",
                    if betas.is_empty() {
                        format!("$k = {k}$ alone")
                    } else {
                        format!("$k = {k}$ alone $(\\beta = {})$", list(&betas))
                    },
                    reference,
                    verdict,
                ));
            }
        }
        if betas.len() > 1 {
            for &beta in &betas {
                let (reference, verdict) = judge(self.worst(n, |_, b| b == Some(beta)));
                out.push(Alternative::new(
                    "the dissipation's form",
                    format!(
                        "$\\beta = {beta}$ alone ($P = -\\epsilon m a g \\Omega^{{{beta}}}$; $k = {}$)",
                        list(&ks)
                    ),
                    reference,
                    verdict,
                ));
            }
        }
        out
    }
}

/// The worse of `parts` by [`crate::harness::worst_order`], with the alternatives of `runs`
/// (at `small`, against `claimed_order`) when the part that decides is the one whose comparison
/// is `judged`: the alternatives are that part's choices, not the others'.
pub(crate) fn worse_part(
    parts: Vec<(String, Finding)>,
    judged: &str,
    runs: &DiskRuns,
    small: &[f64],
    claimed_order: f64,
) -> Finding {
    let f = crate::harness::worst_order(parts);
    if f.compared == judged {
        f.with_robustness(runs.alternatives(small, claimed_order))
    } else {
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    /// An error that falls as the square of the small parameter for k = 1/4 and stays at 0.4
    /// for k = 1/2: as read (the worst) it fails; k = 1/4 alone holds, so the verdict depends
    /// on k; beta alone fails under each law.
    #[test]
    fn each_parameter_alone_is_judged_on_its_own_runs() {
        let small = [0.2, 0.1, 0.05];
        let mut runs = DiskRuns::default();
        for beta in [Some(2.0), Some(4.0)] {
            for (i, &x) in small.iter().enumerate() {
                runs.add(0.25, beta, small.len(), i, x * x);
                runs.add(0.5, beta, small.len(), i, 0.4);
            }
        }
        let alts = runs.alternatives(&small, 2.0);
        assert_eq!(alts.len(), 5, "{alts:?}");
        let verdict = |what: &str| {
            alts.iter()
                .find(|a| a.alternative.starts_with(what))
                .map(|a| a.verdict)
        };
        assert_eq!(verdict("as read"), Some(Verdict::Fails));
        assert!(matches!(
            verdict("$k = 0.25$ alone"),
            Some(Verdict::HoldsApproximately { .. })
        ));
        assert_eq!(verdict("$k = 0.5$ alone"), Some(Verdict::Fails));
        assert_eq!(verdict(r"$\beta = 2$ alone"), Some(Verdict::Fails));
        let f = Finding::from_order("x", &small, &runs.all(small.len()), 2.0).with_robustness(alts);
        assert_eq!(
            f.verdict,
            Verdict::DependsOn {
                choice: "k of the disk"
            }
        );
    }
}
