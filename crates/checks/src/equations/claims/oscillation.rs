//! Claims of sec. 7: small oscillations about steady motion, their stability, the coincidence
//! of frequencies, and the friction the oscillation needs.

use super::judge::{printed, single, stated, worse};
use super::{
    b_bound, bisect, golden_min, max_growth, mid, mu_required, q_eq54, q_linearized, rolling,
    solve, steady_motion, unit_disk, Bench, Extras, Finding, Method, Model, Problem, Rolling,
    Tolerance, Worst, WIDTH,
};
use crate::robustness::Alternative;

// ------------------------------------------------------------------------------ sec. 7

/// The tilt at which the $b$-linear coefficient of $(k+1)\varpi^2/\Omega_0^2$ changes sign,
/// from the linearized eqs 23-25 (central difference in $b$), by bisection.
pub(super) fn bracket_root_linearized(k: f64) -> f64 {
    let h = 1e-4;
    mid(bisect(0.3, 1.4, 1e-10, |al| {
        q_linearized(k, al, h) - q_linearized(k, al, -h) < 0.0
    }))
}

/// `bracket-negative-angle`: the tilt where eq 54's bracketed $b$-coefficient turns negative,
/// measured on the linearized eqs 23-25 (independent of eq 54): 52.24 deg at $k = 1/4$ (the
/// zero of eq 54's printed bracket agrees), 13 % below "roughly 60", outside the
/// stated 5 %. It is below 60 deg for every $k$ (it tends to 60 only as $k \to \infty$). FAILS.
pub(super) fn bracket_negative_angle(b: &Bench) -> Finding {
    let root = bracket_root_linearized(0.25);
    let printed = match b.paper.eq54_bracket_zero(0.25) {
        Ok(zero) => format!("{:.4} deg", zero.to_degrees()),
        Err(e) => format!("not evaluated ({e})"),
    };
    let others: Vec<String> = [0.1, 0.5, 0.9]
        .iter()
        .map(|&k| {
            format!(
                "$k = {k}$: {:.2} deg",
                bracket_root_linearized(k).to_degrees()
            )
        })
        .collect();
    stated(
        b,
        "bracket-negative-angle",
        Method::Linearization,
        "tilt where eq 54's b-coefficient turns negative, $k = 1/4$ (deg)",
        root.to_degrees(),
        format!(
            "linearization {:.4} deg, eq 54's printed bracket {}; {}",
            root.to_degrees(),
            printed,
            others.join(", ")
        ),
    )
}

/// Lowest tilt at which some $b > 0$ makes $\varpi^2 < 0$ (linearized eqs 23-25, $k$ given): the
/// minimum over $b/a \in (0, 40]$ by golden section, the tilt by bisection.
pub(super) fn instability_onset(k: f64) -> f64 {
    mid(bisect(0.9, 1.55, 1e-9, |al| {
        golden_min(1e-6, 40.0, 1e-9, |beta| q_linearized(k, al, beta)).1 < 0.0
    }))
}

/// `positive-b-unstable-large-tilt`: the region of $(\alpha_0, b > 0)$ where the steady motion
/// is unstable, from the linearized eqs 23-25: it starts at 71.4 deg (k = 1/4), at $b \approx
/// 0.57a$, and at each larger tilt covers only a band of $b$ (large $b$ is stable again). Between
/// the bracket's 52 deg and 71.4 deg every $b > 0$ is stable. The paper's "unstable at large tilt,
/// falls to below about 60 deg" (restated in the summary, sec. 12), read as the onset: the
/// lowest unstable tilt is 19 % above 60, outside the stated 5 %, and fails. Eigenvalues confirm:
/// a positive real part inside the region, none outside it.
///
/// Read as what the fall does ([`super::fall`]): rolling without slip, no start settles into a
/// lower rolling (a conservative nutation); on a table slippery enough that the contact slides
/// ($\mu = 0.2$) every start settles near 35 deg, below 60; on rougher tables it does not slide
/// and does not settle. The verdict depends on whether the contact can slide, with each table's
/// value beside it.
pub(super) fn positive_b_unstable_large_tilt(b: &Bench) -> Finding {
    let k = 0.25;
    let onset = instability_onset(k);
    let (beta_at_onset, _) = golden_min(1e-6, 40.0, 1e-9, |beta| q_linearized(k, onset, beta));
    // Band at 80 degrees from eq 54's printed quadratic (qc + qb beta + qa beta^2 < 0).
    let al80 = 80f64.to_radians();
    let band = b.paper.eq54_quadratic(k, al80);
    let [qc, qb, qa] = band.as_ref().map_or([f64::NAN; 3], |q| *q);
    let disc = (qb * qb - 4.0 * qa * qc).sqrt();
    let (b1, b2) = ((-qb - disc) / (2.0 * qa), (-qb + disc) / (2.0 * qa));
    let inside = max_growth(k, al80, 0.5 * (b1 + b2));
    let outside = [0.05, 0.3, 1.0, 3.0]
        .iter()
        .map(|&beta| max_growth(k, 65f64.to_radians(), beta))
        .fold(f64::NEG_INFINITY, f64::max);
    let above = max_growth(k, al80, 2.0 * b2);
    let eigen_ok = inside > 1e-6 && outside < 1e-9 && above < 1e-9;
    let mut f = stated(
        b,
        "positive-b-unstable-large-tilt",
        Method::Linearization,
        "lowest tilt at which some $b > 0$ is unstable, $k = 1/4$ (deg), against the paper's 60",
        onset.to_degrees(),
        format!(
            "onset {:.3} deg at $b = {:.3} a$; unstable band at 80 deg: $b/a$ in ({:.3}, {:.3}); \
             max Re$(\\lambda) {:.3e}$ inside, {:.1e} at 65 deg, {:.1e} at 80 deg above the band",
            onset.to_degrees(),
            beta_at_onset,
            b1,
            b2,
            inside,
            outside,
            above
        ),
    );
    if let Err(e) = band {
        // The band is eq 54's printed claim: where it cannot be evaluated, neither can the
        // claim (never a failure of the paper).
        f.claimed = f64::NAN;
        f.at = format!("eq 54's right side, from which the band is drawn: {e}");
    } else if !eigen_ok {
        f.verdict = crate::finding::Verdict::Fails;
        f.at = format!("{}; EIGENVALUES DISAGREE", f.at);
    }
    let Some((claimed, Some(within))) = b
        .paper
        .claims
        .iter()
        .find(|c| c.id == "positive-b-unstable-large-tilt")
        .map(|c| (c.claimed_value, c.rule.as_ref().and_then(|r| r.within)))
        .and_then(|(v, w)| Some((b.claim(v?), w)))
    else {
        // Read as anything but "within": the onset alone is judged.
        return f;
    };
    let (runs, account) = super::fall::fall_readings(b, claimed, within);
    f.at = format!("{}; {account}", f.at);
    let onset = Alternative::new(
        "the reading of 'falls to below about 60 deg'",
        format!(
            "as the onset of the instability (eq 54's route): the lowest unstable tilt, \
             within {} % of {claimed}",
            within * 100.0
        ),
        f.reference,
        f.verdict,
    );
    let mut readings = vec![onset];
    readings.extend(runs);
    f.with_robustness(readings)
}

/// `negative-b-always-stable`: on a grid of $k$, $\alpha_0$ and $b$ between eq 30's bound and 0,
/// $(k+1)\varpi^2/\Omega_0^2$ from the linearized eqs 23-25 is positive everywhere (the claim),
/// and equals eq 54's right side, from which the paper draws it (the comparison that carries
/// the claimed side). Derived lower bound: $2k\cos^2\alpha_0/(2k+1) + \sin^2\alpha_0 > 0$.
pub(super) fn negative_b_always_stable(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut lowest = f64::INFINITY;
    for &k in &[0.1, 0.25, 0.5, 0.9, 1.0] {
        for &al in &[0.05, 0.2, 0.5, 0.8, 1.1, 1.4, 1.55] {
            let bound = b_bound(&unit_disk(k), al);
            for &f in &[0.01, 0.25, 0.5, 0.75, 0.99] {
                let beta = f * bound;
                let lin = q_linearized(k, al, beta);
                let floor = 2.0 * k * al.cos().powi(2) / (2.0 * k + 1.0) + al.sin().powi(2);
                lowest = lowest.min(lin / floor);
                let claimed = if lin > 0.0 {
                    b.claim(q_eq54(b, k, al, beta))
                } else {
                    f64::NAN
                };
                w.add(claimed, lin, lin.abs(), || {
                    format!("$k = {k}$, $\\alpha_0 = {al}$, $b = {beta:.4} a$")
                });
            }
        }
    }
    let mut f = Finding::from_worst(
        Method::Linearization,
        "$(k+1) \\varpi^{2} / \\Omega_0^{2}$ for $b < 0$: linearized eqs 23-25 against eq 54, and its sign",
        w,
        linearization_tolerance(),
    )
    .in_unit("1");
    f.at = format!(
        "{}; smallest ratio to the derived positive lower bound {lowest:.4}",
        f.at
    );
    f
}

/// Frequencies from exact Jacobians: $\varpi^2 = -\mathrm{tr}(J^2)/2$ cancels products of
/// Jacobian entries up to $\Omega_0^4$ while $\varpi^2 \sim \Omega_0^2$; at the grid's largest
/// $\Omega_0$ that loses up to about 1e4 ulp.
pub(super) fn linearization_tolerance() -> Tolerance {
    Tolerance {
        value: 1e-10,
        rule: "linearization: exact Jacobian, $\\varpi^{2} = -\\operatorname{tr}(J^{2})/2$ cancels up to ~1e5 ulp: 1e-10 relative".into(),
    }
}

/// $\varpi/\Omega_0$ at $b = 0$ from the linearized eqs 23-25.
pub(super) fn ratio_b0(k: f64, al: f64) -> f64 {
    (q_linearized(k, al, 0.0) / (k + 1.0)).sqrt()
}

/// `ratio-uniform-disk-077`: $\varpi/\Omega_0$ at $b = 0$ from the linearized eqs 23-25 as
/// $\alpha_0 \to 0$ ($k = 1/4$): it tends to $\sqrt{3/5}$ at second order in $\alpha_0$ and
/// rounds to the printed 0.77.
pub(super) fn ratio_uniform_disk_077(b: &Bench) -> Finding {
    let k = 0.25;
    let limit = ratio_b0(k, 1e-5);
    let printed = stated(
        b,
        "ratio-uniform-disk-077",
        Method::Linearization,
        "$\\varpi / \\Omega_0$ at $b = 0$, $\\alpha_0 \\to  0$, $k = 1/4$ (printed 0.77)",
        limit,
        "linearization at $\\alpha_0 = 1e-5$".into(),
    );
    let alphas = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3];
    let errors: Vec<f64> = alphas
        .iter()
        .map(|&al| (ratio_b0(k, al) - b.claim((0.6f64).sqrt())).abs())
        .collect();
    let order = Finding::from_order(
        "$\\varpi / \\Omega_0$ at $b = 0$ approaching $\\sqrt{3/5} (k = 1/4)$",
        &alphas,
        &errors,
        2.0,
    );
    worse(printed, order)
}

/// `ratio-hoop-one`: $\varpi/\Omega_0 \to 1$ for $k = 1/2$, $b = 0$, from the linearized eqs
/// 23-25; the error falls as $\alpha_0^2$ (exactly $1 - \sqrt{1 - \sin^2\alpha_0/3}$).
pub(super) fn ratio_hoop_one(b: &Bench) -> Finding {
    let alphas = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3];
    let errors: Vec<f64> = alphas
        .iter()
        .map(|&al| (ratio_b0(0.5, al) - b.claim(1.0)).abs())
        .collect();
    Finding::from_order(
        "$\\varpi / \\Omega_0$ at $b = 0$ approaching 1 for a hoop $(k = 1/2)$",
        &alphas,
        &errors,
        2.0,
    )
}

/// `b-of-order-a-alpha`: the paper takes $b = \alpha_0 a$ at small tilt. By the exact contact
/// force (eq 20) a steady motion rolls without slipping ($\mu = 1$) only up to $b/(a\alpha_0) =
/// 0.25$ for $k = 1/4$ as $\alpha_0 \to 0$ (bisection at $\alpha_0 = 10^{-4}$; $\mu k$ in
/// general, from eq 42): at $b = \alpha_0 a$ it would need $\mu = 1/k = 4$. "Of order", read as
/// within a factor 3 (claims.yaml), fails there. The paper does not say at which tilt "small"
/// is read; it uses $b = \alpha_0 a$ at 0.2 rad (the beat tilt of sec. 7), where the largest
/// rolling $b/(a\alpha_0)$ is 0.357, within the factor: the verdict depends on the point of
/// evaluation, and the finding says so with both values.
pub(super) fn b_of_order_a_alpha(b: &Bench) -> Finding {
    let largest = |k: f64, al: f64| {
        mid(bisect(1e-3, 10.0, WIDTH, |c| {
            mu_required(k, al, c * al) > 1.0
        }))
    };
    let judge = |al: f64, ratio: f64| {
        stated(
            b,
            "b-of-order-a-alpha",
            Method::Derivation,
            "largest $b / (a \\alpha_0)$ rolling without slipping at $\\mu = 1$, $k = 1/4$, against the assumed 1",
            ratio,
            format!(
                "$\\alpha_0 = {al}$: ${ratio:.5} (k = 1/4)$, ${:.5} (k = 1/2)$; required $\\mu$ at $b = \\alpha_0 a$: {:.4}",
                largest(0.5, al),
                mu_required(0.25, al, al)
            ),
        )
    };
    let points = [
        ("$\\alpha_0 \\to  0$ (1e-4 rad)", 1e-4),
        (
            "$\\alpha_0 = 0.2$ rad, where sec. 7 uses $b = \\alpha_0 a$",
            0.2,
        ),
    ];
    let judged: Vec<(&str, Finding)> = points
        .iter()
        .map(|&(what, al)| (what, judge(al, largest(0.25, al))))
        .collect();
    let alternatives = judged
        .iter()
        .map(|(what, f)| Alternative::new("the point of evaluation", *what, f.reference, f.verdict))
        .collect();
    judged[0].1.clone().with_robustness(alternatives)
}

/// `coincidence-eq58`: the tilt where eq 58's $\varpi/\Omega_0 = \sqrt{(3 + 10\alpha_0)/5}$ equals 1,
/// by bisection: 0.2 rad, as the paper computed it (sec. 7 takes the number from eq 58, where it
/// is exact). The same coincidence in the full theory (the linearized eqs 23-25 with
/// $b = \alpha_0 a$, and eq 54, which agrees) lies at 0.168 rad (9.65 deg): the tool's own
/// construction, shown in the finding's `at` as a finding and not judged against the paper's
/// number, which the paper never computed that way.
pub(super) fn coincidence_eq58(b: &Bench) -> Finding {
    let root = mid(bisect(1e-3, 1.0, WIDTH, |al| {
        ((3.0 + 10.0 * al) / 5.0).sqrt() > 1.0
    }));
    let (lin, eq54) = coincidence_tilts(b);
    single(
        Method::Derivation,
        "tilt where eq 58 gives $\\varpi = \\Omega_0$ (rad)",
        b.claim(printed(b, "coincidence-eq58")),
        root,
        Tolerance::bisection(WIDTH),
        format!(
            "bisection on eq 58; the tool's finding, not the paper's claim: the full theory \
             (linearized eqs 23-25 with $b = \\alpha_0 a$, $k = 1/4$) puts the coincidence at {lin:.6} \
             rad ({:.2} deg), eq 54 at {eq54:.6} rad",
            lin.to_degrees()
        ),
    )
}

/// The tilt where $\varpi = \Omega_0$ with $b = \alpha_0 a$, $k = 1/4$, from the linearized eqs
/// 23-25 (and from eq 54, for comparison).
pub(super) fn coincidence_tilts(b: &Bench) -> (f64, f64) {
    let k = 0.25;
    let lin = mid(bisect(0.01, 0.6, WIDTH, |al| {
        q_linearized(k, al, al) > k + 1.0
    }));
    let eq54 = mid(bisect(0.01, 0.6, WIDTH, |al| {
        q_eq54(b, k, al, al) > k + 1.0
    }));
    (lin, eq54)
}

/// `rattling-needs-more-friction`: the friction coefficient a rolling disk needs, $|F_h|/F_z$
/// from the exact contact force (eq 20's premise $\mathbf F = m\ddot{\mathbf r}_{cm} +
/// mg\hat{\mathbf z}$, the model's own rates), at its peak along motions of eqs 23-25 that
/// oscillate about the steady motion $\alpha_0 = 0.3$, $b = 0.05a$ ($k = 1/4$) with growing
/// amplitude (kicks of $\dot\alpha$, which leave the oscillation centred near $\alpha_0$; a
/// push of $\alpha$ itself moves the centre up, where less friction is needed, and confounds
/// the two): it rises monotonically above the steady requirement (the claim). The comparison
/// that carries the claimed side is the requirement at zero amplitude against the steady closed
/// form, to the solver's tolerance.
pub(super) fn rattling_needs_more_friction(b: &Bench) -> Finding {
    let disk = unit_disk(0.25);
    let model = Rolling::<4>::new(disk, Extras::default(), None);
    let (alpha0, beta) = (0.3, 0.05);
    let Ok(m0) = steady_motion(&disk, alpha0, beta) else {
        panic!("the steady motion at $\\alpha_0 = 0.3$, $b = 0.05 a$ exists (eq 30)")
    };
    let peak = |push: f64| {
        let mut m = m0;
        m.alpha_dot += push;
        let sol = solve(
            Problem::new(&model, 0.0, model.state(&m), 20.0).sampled(5e-3),
            &b.settings(),
        )
        .expect("valid settings");
        sol.y
            .iter()
            .map(|y| {
                let [fz, fr, f2] = rolling::contact_force(&disk, &model.motion(y), &model.rates(y));
                fr.hypot(f2) / fz
            })
            .fold(0.0, f64::max)
    };
    let pushes = [0.0, 0.01, 0.02, 0.05, 0.1];
    let peaks: Vec<f64> = pushes.iter().map(|&p| peak(p)).collect();
    let rising = peaks.windows(2).all(|p| p[1] > p[0]);
    let steady = mu_required(0.25, alpha0, beta);
    let mut f = single(
        Method::Integration,
        "friction coefficient needed to roll at zero oscillation, against the steady motion's \
         ($k = 1/4$, $\\alpha_0 = 0.3$, $b = 0.05 a$)",
        b.claim(steady),
        peaks[0],
        Tolerance::solver(b.rtol),
        format!(
            "peak $|F_h| / F_z$ after kicks of $\\dot\\alpha$ by {} $\\sqrt{{g/a}}$: {} ({})",
            pushes
                .iter()
                .map(|p| format!("{p}"))
                .collect::<Vec<_>>()
                .join(", "),
            peaks
                .iter()
                .map(|p| format!("{p:.5}"))
                .collect::<Vec<_>>()
                .join(", "),
            if rising {
                "rising with the amplitude"
            } else {
                "NOT RISING with the amplitude"
            }
        ),
    )
    .in_unit("1");
    if !rising {
        f.verdict = crate::finding::Verdict::Fails;
    }
    f
}

/// `summary-nutation-10-15-deg`: the summary's "about 10 to 15 degrees" for the beating
/// nutation, against the tilt where $\varpi = \Omega_0$ with $b = \alpha_0 a$, $k = 1/4$: 9.65 deg
/// from the linearized eqs 23-25 (eq 58's approximation gives 0.2 rad, 11.46 deg). "About" is
/// read as for every number the paper did not compute: each end of the range within 5 %
/// (claims.yaml), so 9.65 deg, 3.5 % below 10, holds.
pub(super) fn summary_nutation_10_15_deg(b: &Bench) -> Finding {
    let (lin, eq54) = coincidence_tilts(b);
    stated(
        b,
        "summary-nutation-10-15-deg",
        Method::Linearization,
        "tilt where $\\varpi = \\Omega_0$ with $b = \\alpha_0 a$, $k = 1/4$ (deg)",
        lin.to_degrees(),
        format!(
            "linearization {:.2} deg, eq 54 {:.2} deg; eq 58 gives 0.2 rad = {:.2} deg",
            lin.to_degrees(),
            eq54.to_degrees(),
            0.2f64.to_degrees()
        ),
    )
}
