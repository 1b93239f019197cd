//! Eqs 52-53: where steady motion turns unstable, against integrations.

use super::frequency::worse;
use super::{
    add_threshold, bisect, printed_threshold, solve, varpi2, Bench, Bindings, Disk, Ending, Event,
    Extras, Finding, Method, Model, Motion, Problem, Rolling, State, Tolerance, Worst, FRAC_PI_2,
    KS,
};
use physics::disk::toy_sized;

/// Integrations last $N$ natural times $\sqrt{a/g}$. The upright disk is kicked with a small
/// $\dot\alpha_0$ (which excites only the oscillation: $\Omega$ and $\omega_1$ follow $\alpha$ by
/// the first-order eqs 23 and 25 and so start on the mode); it is stable when $\dot\alpha$
/// turns back, which it does within $T$ iff $\varpi > \pi/2T$ (unstable: $\dot\alpha \propto
/// \cosh\sigma t$ never turns back). Near both thresholds $(k+1)\varpi^2 = (g/a)(x/x_* - 1)$ for
/// the squared rate $x$ with threshold $x_*$ (eq 50 at $\alpha_0 = \pi/2$, whose linearization is
/// verified in eqs 50-51), so the located threshold in $x$ is high by at most
/// $(k+1)(\pi/2)^2/N^2$ relatively; half that for $\sqrt{x}$.
pub(super) const N_NATURAL: f64 = 2000.0;

pub(super) fn finite_time_tolerance(k: f64, width: f64, squared: bool) -> Tolerance {
    let bias = (k + 1.0) * FRAC_PI_2 * FRAC_PI_2 / (N_NATURAL * N_NATURAL);
    let bias = if squared { bias } else { 0.5 * bias };
    Tolerance {
        value: bias + 2.0 * width,
        rule: format!(
            "threshold from integrations of ${N_NATURAL} \\sqrt{{a/g}}$: finite-time bias \
             $(k+1) (\\pi/2)^{{2}} / N^{{2}}{}$ plus twice the bracket ({width:e})",
            if squared { "" } else { " / 2" }
        ),
    }
}

/// Does the upright disk with $(\Omega, \omega_1)$, kicked with
/// $\dot\alpha_0 = 10^{-8}\sqrt{g/a}$, turn back (its $\dot\alpha$ changes sign) within $N$
/// natural times, before it falls $10^{-3}$ rad off upright (a disk that falls may turn back
/// later into another motion: that is not stability)?
pub(super) fn turns_back(b: &Bench, d: &Disk, precession: f64, spin: f64) -> bool {
    let model = Rolling::<4>::new(*d, Extras::default(), None);
    let m = Motion {
        alpha: FRAC_PI_2,
        alpha_dot: 1e-8 * d.g_over_a().sqrt(),
        precession,
        spin,
    };
    let t = N_NATURAL / d.g_over_a().sqrt();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&m), t)
            .stop_when(Event::new("$\\dot\\alpha$ turns back", |y: &State<4>| y[1]))
            .stop_when(Event::new("falls 1e-3 rad off upright", |y: &State<4>| {
                1e-3 - (y[0] - FRAC_PI_2).abs()
            })),
        &b.settings(),
    )
    .expect("valid settings");
    matches!(sol.ending, Ending::Event { index: 0, .. })
}

/// Eq 52, $\omega_{10}^2 > \dfrac{g}{2(2k+1)a}$: a wheel rolling straight is stable only above it.
///
/// Threshold: located by bisection on the outcome of integrations (does the wheel, kicked off
/// upright, turn back within 2000 natural times?), and by bisection on the sign
/// of the linearized $\varpi^2 = e_2(J)$; both compared with the claimed bound on
/// $\omega_{10}^2$.
pub(super) fn eq52(b: &Bench) -> Finding {
    threshold_check(b, 52)
}

/// Eq 53, $|\Omega_0| > \sqrt{\dfrac{g}{a(k+1)}}$: a disk spinning about a vertical diameter is
/// stable only above it.
///
/// Threshold: as for eq 52, on $|\Omega_0|$ with $\omega_{10} = 0$.
pub(super) fn eq53(b: &Bench) -> Finding {
    threshold_check(b, 53)
}

/// Eqs 52 and 53: the threshold on $\omega_{10}$ (eq 52, printed on its square) or on
/// $|\Omega_0|$ (eq 53) where the upright disk becomes stable, located by bisection on the
/// linearized $\varpi^2$ and on integrations; compared with the edge the printed inequality gives
/// (solved for $\omega_{10}$ or $\Omega_0$), and its direction with the linearization's verdict
/// 0.1 % either side.
pub(super) fn threshold_check(b: &Bench, which: u32) -> Finding {
    let width = 1e-10;
    let width_int = 1e-6;
    let mut out: Option<Finding> = None;
    for k in KS {
        let d = toy_sized(k);
        let ga = d.g_over_a();
        // x is omega_10 (eq 52) or |Omega_0| (eq 53): the state (Omega, omega_1) at x.
        let y_of = |x: f64| if which == 52 { (0.0, x) } else { (x, 0.0) };
        let (lo, hi) = (0.3 * ga.sqrt(), 3.0 * ga.sqrt());
        let stable = |x: f64| {
            let (om, w) = y_of(x);
            varpi2(&d, &[FRAC_PI_2, 0.0, om, w]) > 0.0
        };
        let lin = {
            let (l, h) = bisect(lo, hi, width, stable);
            0.5 * (l + h)
        };
        let int = {
            let (l, h) = bisect(lo, hi, width_int, |x| {
                let (om, w) = y_of(x);
                turns_back(b, &d, om, w)
            });
            0.5 * (l + h)
        };
        let quantity = if which == 52 { "omega_10" } else { "Omega_0" };
        let bind = Bindings::new()
            .scalar("g", d.g)
            .scalar("a", d.a)
            .scalar("k", k);
        let probes = [lin * (1.0 - 1e-3), lin * (1.0 + 1e-3)];
        let printed = printed_threshold(b, which, quantity, &bind, (lo, hi), probes);
        let allowed = probes.map(stable);
        let mut wl = Worst::default();
        add_threshold(b, &mut wl, &printed, lin, allowed, &|| {
            format!("$k = {k}$, linearization")
        });
        let mut wi = Worst::default();
        wi.add(b.claim(printed.edge), int, int, || {
            format!("{}: $k = {k}$, integrations", printed.relation)
        });
        let what = if which == 52 {
            "$\\omega_{10}$ threshold"
        } else {
            "$|\\Omega_0|$ threshold"
        };
        let fl = Finding::from_worst(
            Method::Linearization,
            format!("{what}: the printed edge and direction against the sign change of the linearized $\\varpi^{{2}}$"),
            wl,
            Tolerance::bisection(width));
        let fi = Finding::from_worst(
            Method::Threshold,
            format!("{what}: the printed edge against bisection on integrations (does a kick turn back?)"),
            wi,
            finite_time_tolerance(k, width_int, false));
        // Both edges are angular rates (omega_10 or |Omega_0|).
        let f = worse(fi, fl).in_unit("rad/s");
        out = Some(match out {
            None => f,
            Some(o) => worse(o, f),
        });
    }
    out.unwrap_or_else(|| {
        Finding::from_worst(
            Method::Threshold,
            "no disk was swept",
            Worst::default(),
            Tolerance::bisection(width),
        )
    })
}
