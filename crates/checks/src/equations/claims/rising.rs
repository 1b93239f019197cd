//! Sec. 10's claim that needs the sliding model: rising near the vertical.

use super::judge::{printed, single};
use super::{frictionless_vertical_threshold, mid, Bench, Disk, Finding, Method, Tolerance, WIDTH};
use studies::sliding::rising::{rising, LAUNCH_OVER_THRESHOLD, LAUNCH_TILT};

/// The smallest lasting gain of tilt counted as rising (deg), and the largest counted as none:
/// a conservative launch returns to its launch tilt to about 1e-7 deg at rtol 1e-10 (the
/// sampled minimum of a turning point); a slipping one gained 2.7-3.3 deg.
const RISEN: f64 = 1.0;
const NONE: f64 = 0.01;

/// `rising-needs-slip`: a disk launched at $\alpha_0 = 85°$ turning about the vertical through
/// its centre at 1.5 times eq 65's sleeping threshold $\sqrt{g/ak}$ (the section's premise) is
/// run without friction, with Coulomb friction for several $\mu$, and rolling from the same tilt
/// and rate ([`studies::sliding::rising`]). The claim holds when some sliding launch gains more
/// than 1 deg for good and neither the rolling nor the frictionless one gains more than 0.01
/// deg. The comparison that carries the printed number is the premise: the threshold the
/// launch is scaled by (printed coefficient 1 of $\sqrt{g/ak}$) against the frictionless
/// linearization at $\alpha = \pi/2$ (eqs 61-62, bisection), as for
/// `frictionless-threshold-uniform`.
pub(super) fn rising_needs_slip(b: &Bench) -> Finding {
    let k = 0.25;
    let coefficient = b.claim(printed(b, "rising-needs-slip"));
    // frictionless_vertical_threshold is in sqrt(g/a); sqrt(g/(a k)) = sqrt(g/a) / sqrt(k).
    let exact = mid(frictionless_vertical_threshold(k)) * k.sqrt();
    let mut f = single(
        Method::Linearization,
        "the launch's premise, eq 65's sleeping threshold without friction (in $\\sqrt{g/(a k)}$, $k = 1/4$)",
        coefficient,
        exact,
        Tolerance::bisection(WIDTH),
        "bisection on $\\varpi^{2}$ of the linearized eqs 61-62 at $\\alpha = \\pi/2$".into(),
    );
    let Ok(disk) = Disk::new(0.0375, k, 0.4, 9.81) else {
        unreachable!("the toy disk is valid")
    };
    let threshold = coefficient * (disk.g / (disk.a * k)).sqrt();
    let study = match rising(&disk, threshold, &b.settings()) {
        Ok(s) => s,
        Err(e) => {
            f.verdict = crate::finding::Verdict::Fails;
            f.at = format!("the launches could not be run: {e}");
            return f;
        }
    };
    let cases = study
        .cases
        .iter()
        .map(|c| match c.contact {
            "no friction" => format!("no friction: {:+.2} deg", c.rise_deg),
            "rolling" => format!("rolling: {:+.2} deg (no slip)", c.rise_deg),
            _ => format!(
                "$\\mu {}$: {:+.2} deg (slid {:.3} s)",
                c.mu, c.rise_deg, c.slip_time
            ),
        })
        .collect::<Vec<_>>()
        .join("; ");
    let with = study.largest_rise_with_slip();
    let without = study.largest_rise_without_slip();
    let holds = with > RISEN && without < NONE;
    f.at = format!(
        "{}; launch at {:.0} deg turning at {LAUNCH_OVER_THRESHOLD} × the threshold about the \
         vertical, contact sliding at ${:.3} m/$s; lasting gain of tilt over {} s (lowest tilt in the \
         second half minus the launch tilt): {cases}. {}",
        f.at,
        LAUNCH_TILT.to_degrees(),
        study.launch_slip,
        studies::sliding::rising::DURATION,
        if holds {
            format!(
                "Rises only when it slides (by up to {with:.2} deg); with $\\mu \\geq  0.3$ the slip stops \
                 within milliseconds and the disk ends lower"
            )
        } else {
            format!(
                "CONTRADICTED: largest gain with slip {with:.2} deg (rising needs > {RISEN}), \
                 without slip {without:.3} deg (none needs < {NONE})"
            )
        }
    );
    if !holds {
        f.verdict = crate::finding::Verdict::Fails;
    }
    f
}
