//! Eqs 33-37: section 5's vector relations at b = 0, against the lab-frame Newton-Euler model.

use super::super::steady_reference::{steady_ref, KS};
use super::{
    printed_relations, solve, Bench, Bindings, Contact, Disk, Finding, LabFrame, Method, Problem,
    Snapshot, State, Tolerance, Vector3, Worst, PI,
};
use crate::harness::disk_constants;
use numerics::memo::{bits, Memo};
use physics::disk::toy_sized;
use std::sync::Arc;

/// Tilts of the section 5 checks.
pub(super) const LAB_ALPHAS: [f64; 3] = [0.1, 0.8, 1.4];

/// Samples per precession period of a lab run: $\Omega_0 h = 2\pi/320 \approx 0.02$, so the
/// seven-point derivative's truncation, $(\Omega_0 h)^6/140 \approx 4\times10^{-13}$ of
/// $|\dot{\mathbf L}|$ ($\mathbf L$ turns uniformly at $\Omega_0$), and its round-off,
/// about $2\epsilon/(\Omega_0 h\cos\alpha_0) \approx 10^{-13}$ at $\alpha_0 = 1.4$, both stay far
/// below [`Tolerance::solver`] at the default rtol (measured: 5e-13 worst).
pub(super) const LAB_SAMPLES: usize = 320;

/// Every how many samples a lab run's state is compared with a claim (32 points per run).
pub(super) const LAB_STRIDE: usize = 10;

/// A $b = 0$ steady motion integrated by the lab-frame Newton-Euler model over one precession
/// period, with what is measured on it.
pub(super) struct LabSteady {
    pub(super) k: f64,
    pub(super) alpha0: f64,
    pub(super) disk: Disk,
    pub(super) lab: LabFrame,
    /// Sample times (uniform).
    pub(super) t: Vec<f64>,
    /// The lab states sampled.
    pub(super) y: Vec<State<13>>,
    /// The geometry of each sample.
    pub(super) snaps: Vec<Snapshot>,
    /// The angular momentum about the centre of mass, $R\,I\boldsymbol\omega_b$ (lab components).
    pub(super) l: Vec<Vector3<f64>>,
    /// The precession rate: the heading's (unwrapped) advance over the run divided by its time.
    pub(super) precession: f64,
    /// The relative spin: the face angle's (unwrapped) advance over the run divided by its time.
    pub(super) rel_spin: f64,
    /// The largest departure from a steady $b = 0$ motion along the run: $|\alpha - \alpha_0|/\alpha_0$
    /// and the centre's speed over $a|\Omega_0|$.
    pub(super) unsteadiness: f64,
}

/// The advance per unit time of an angle sampled in $(-\pi, \pi]$, unwrapped sample to sample.
pub(super) fn angle_rate(t: &[f64], angles: &[f64]) -> f64 {
    let advance: f64 = angles
        .windows(2)
        .map(|w| (w[1] - w[0] + PI).rem_euclid(2.0 * PI) - PI)
        .sum();
    advance / (t[t.len() - 1] - t[0])
}

impl LabSteady {
    /// The $b = 0$ steady motion of the rolling model (Newton on eq 24 at $\omega_{10} = 0$, not
    /// the paper's eq 31), precessing with the sign `sign`, started in the lab model (heading
    /// 0.3, centre at (0.01, -0.02) m, face angle 0.7: nothing special) and integrated over one
    /// precession period. Its steadiness is measured on the lab run itself.
    fn run(bench: &Bench, k: f64, alpha0: f64, sign: f64) -> Option<Self> {
        let d = toy_sized(k);
        let mut m = steady_ref(&d, alpha0, 0.0)?;
        m.precession *= sign;
        let lab = LabFrame::new(d, Contact::Rolling);
        let y0 = lab.state_from(&m, 0.3, [0.01, -0.02], 0.7);
        let period = 2.0 * PI / m.precession.abs();
        let sol = solve(
            Problem::new(&lab, 0.0, y0, period).sampled(period / LAB_SAMPLES as f64),
            &bench.settings(),
        )
        .ok()?;
        if !sol.ending.is_complete() {
            return None;
        }
        let snaps: Vec<Snapshot> = sol.y.iter().map(|y| lab.snapshot(y)).collect();
        let inertia = Vector3::new(d.i11(), d.i22(), d.i22());
        let l = snaps
            .iter()
            .map(|s| s.rotation * inertia.component_mul(&s.omega_body))
            .collect();
        let headings: Vec<f64> = snaps.iter().map(Snapshot::heading).collect();
        let faces: Vec<f64> = snaps.iter().map(Snapshot::face).collect();
        let unsteadiness = snaps
            .iter()
            .map(|s| {
                ((s.alpha() - alpha0).abs() / alpha0)
                    .max(s.velocity.norm() / (d.a * m.precession.abs()))
            })
            .fold(0.0, f64::max);
        Some(Self {
            k,
            alpha0,
            disk: d,
            precession: angle_rate(&sol.t, &headings),
            rel_spin: angle_rate(&sol.t, &faces),
            t: sol.t,
            y: sol.y,
            lab,
            snaps,
            l,
            unsteadiness,
        })
    }

    /// Every lab run of the section 5 checks: the inertia factors [`KS`], tilts
    /// [`LAB_ALPHAS`], both senses of precession.
    /// Computed once per solver setting and shared by eqs 33-37 (they differ only in what they
    /// compare along the runs).
    pub(super) fn all(bench: &Bench) -> Arc<Vec<Self>> {
        type Key = ([u64; 1], physics::solve::Method);
        static RUNS: Memo<Key, Arc<Vec<LabSteady>>> = Memo::new();
        RUNS.get((bits([bench.rtol]), bench.method), || {
            Arc::new(Self::integrate_all(bench))
        })
    }

    fn integrate_all(bench: &Bench) -> Vec<Self> {
        let mut out = Vec::new();
        for k in KS {
            for alpha0 in LAB_ALPHAS {
                for sign in [1.0, -1.0] {
                    if let Some(run) = Self::run(bench, k, alpha0, sign) {
                        out.push(run);
                    }
                }
            }
        }
        out
    }

    /// The indices compared: every [`LAB_STRIDE`]-th sample, three in from either end (room
    /// for the seven-point derivative).
    fn points(&self) -> impl Iterator<Item = usize> {
        (3..self.t.len() - 3).step_by(LAB_STRIDE)
    }

    /// $d\mathbf L/dt$ at sample `i`, by the seven-point central difference (error
    /// $h^6 L^{(7)}/140$) of the sampled angular momentum.
    fn l_dot(&self, i: usize) -> Vector3<f64> {
        let h = (self.t[i + 3] - self.t[i - 3]) / 6.0;
        let l = &self.l;
        (45.0 * (l[i + 1] - l[i - 1]) - 9.0 * (l[i + 2] - l[i - 2]) + (l[i + 3] - l[i - 3]))
            / (60.0 * h)
    }

    /// The rate $\omega$ about axis 3 measured at sample `i`: $|\boldsymbol\omega|$ with the sign
    /// of $\boldsymbol\omega\cdot\hat{\mathbf 3}$.
    fn omega3(&self, i: usize) -> f64 {
        let s = &self.snaps[i];
        s.omega.norm().copysign(s.omega.dot(&s.e3))
    }

    /// Where, in words.
    fn at(&self, i: usize, what: &str) -> String {
        format!(
            "$k = {}$, $\\alpha_0 = {}$, $\\Omega_0 = {:.4}$ rad/s ($b = 0$, lab frame), $t = {:.5}$ s: {what}",
            self.k, self.alpha0, self.precession, self.t[i]
        )
    }

    /// Records the run's departure from steadiness (the premise of every section 5 claim).
    fn add_steadiness(&self, w: &mut Worst) {
        w.add(self.unsteadiness, 0.0, 1.0, || {
            self.at(
                self.t.len() - 1,
                "largest departure of the lab run from steady $b = 0$ motion (premise)",
            )
        });
    }
}

/// What a sample of a lab run gives the paper's symbols of sec. 5 ($b = 0$), all measured on the
/// lab-frame Newton-Euler run: the triad, $\alpha_0$, the precession and relative spin rates
/// (heading and face angle over the run), $\omega$ about axis 3, $\mathbf L = RI\boldsymbol\omega_b$,
/// its rate (seven-point difference), the contact torque $\boldsymbol\rho\times\mathbf F$, the
/// moment $I_{33}$ from the lab's inertia tensor, and the precession vector (vertical part the
/// heading's rate, horizontal part $\dot\alpha\hat{\mathbf 2}$).
pub(super) fn lab_bindings(run: &LabSteady, i: usize) -> Bindings<f64> {
    let d = &run.disk;
    let s = &run.snaps[i];
    let inertia = Vector3::new(d.i11(), d.i22(), d.i22());
    let e3_body = s.rotation.inverse() * s.e3;
    let i33 = e3_body.dot(&inertia.component_mul(&e3_body));
    disk_constants(d)
        .scalar("alpha_0", s.alpha())
        .scalar("Omega_0", run.precession)
        .scalar("omega_rel", run.rel_spin)
        .scalar("omega_3", run.omega3(i))
        .scalar("I_33", i33)
        .vector("e1", s.e1)
        .vector("e2", s.e2)
        .vector("e3", s.e3)
        .vector("z_hat", Vector3::z())
        .vector("omega_vec", s.omega)
        .vector("L", run.l[i])
        .vector("L_rate", run.l_dot(i))
        .vector("N", s.rho.cross(&run.lab.contact_force(&run.y[i])))
        .vector(
            "Omega_0_vec",
            s.motion().alpha_dot * s.e2 + run.precession * Vector3::z(),
        )
}

/// Eqs 33-37 share this: every printed relation of eq `n` at 32 samples of each lab run,
/// relative to `scale(run, i)`.
pub(super) fn lab_relations(
    b: &Bench,
    n: u32,
    scale: impl Fn(&LabSteady, usize) -> f64,
    what: &str,
) -> Worst {
    let mut w = Worst::default();
    for run in LabSteady::all(b).iter() {
        run.add_steadiness(&mut w);
        for i in run.points() {
            printed_relations(b, n, &lab_bindings(run, i), scale(run, i), &mut w, &|| {
                run.at(i, what)
            });
        }
    }
    w
}

/// Eq 33, $\mathbf L = I_{33}\omega\hat{\mathbf 3} = k m a^2\omega\hat{\mathbf 3}$ at $b = 0$.
///
/// Independent model: the $b = 0$ steady motion (solved by Newton on the rolling model, its
/// steadiness measured on the lab run) integrated by the lab-frame Newton-Euler model over one
/// precession period; at 32 samples the angular momentum computed in the lab,
/// $R\,I\boldsymbol\omega_b$, against both printed forms, with $\omega$ measured
/// ($|\boldsymbol\omega|$ with the sign of $\boldsymbol\omega\cdot\hat{\mathbf 3}$),
/// $\hat{\mathbf 3}$ the lab's direction to the lowest rim point, and $I_{33} =
/// \hat{\mathbf 3}\cdot R I R^T\hat{\mathbf 3}$ from the lab's inertia tensor.
pub(super) fn eq33(b: &Bench) -> Finding {
    let w = lab_relations(b, 33, |run, i| run.l[i].norm(), "L, relative to $|L|$");
    Finding::from_worst(
        Method::IndependentModel,
        "the printed forms of L against $R I \\boldsymbol\\omega_b$ along lab-frame $b = 0$ steady runs, relative to $|L|$",
        w,
        Tolerance::solver(b.rtol))
    .in_unit("kg m^2/s")
}

/// Eq 34, $\mathbf N = a\hat{\mathbf 3}\times m g\hat{\mathbf z} = \dfrac{d\mathbf L}{dt}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, $\mathbf N$ is the torque about the
/// centre of the contact force the lab model solves from the rolling condition,
/// $\boldsymbol\rho\times\mathbf F$, and $d\mathbf L/dt$ the rate of the lab's angular momentum
/// (seven-point central difference of the sampled $\mathbf L(t)$); relative to $|\mathbf N|$.
pub(super) fn eq34(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        34,
        |run, i| {
            lab_bindings(run, i)
                .get("N")
                .and_then(|v| v.vector().ok())
                .map_or(1.0, |v| v.norm())
        },
        "N, relative to its norm",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed torque against the lab's contact torque $\\rho x F$ and the lab run's $dL/dt$ (seven-point difference), relative to $|N|$",
        w,
        Tolerance::solver(b.rtol))
}

/// Eq 35, $\dfrac{d\mathbf L}{dt} = \vec\Omega_0\times\mathbf L$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, with $\vec\Omega_0$ the precession
/// vector MEASURED on the lab run, against the lab run's $d\mathbf L/dt$ (seven-point central
/// difference), relative to its norm.
pub(super) fn eq35(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        35,
        |run, i| run.l_dot(i).norm(),
        "$dL/dt$, relative to $|dL/dt|$",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "$\\Omega_0 x L$ (the lab run's measured precession) against the lab run's $dL/dt$, relative to $|dL/dt|$",
        w,
        Tolerance::solver(b.rtol))
}

/// Eq 36, $\vec\Omega_0 = -\dfrac{g}{a k\omega}\hat{\mathbf z}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, with $\omega$ measured in the lab
/// ($|\boldsymbol\omega|$ with the sign of $\boldsymbol\omega\cdot\hat{\mathbf 3}$) at each sample,
/// against the precession vector measured on the run (vertical part the heading's advance over
/// one period divided by its time, horizontal part $\dot\alpha\hat{\mathbf 2}$ read from the lab
/// state); relative to the measured $|\Omega_0|$. Both senses of precession.
pub(super) fn eq36(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        36,
        |run, _| run.precession.abs(),
        "$\\Omega_0$, relative to $|\\Omega_0|$",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed precession vector ($\\omega$ measured in the lab) against the lab run's measured precession vector, relative to $|\\Omega_0|$",
        w,
        Tolerance::solver(b.rtol))
}

/// Eq 37, $\vec\omega = (-\Omega_0\cos\alpha_0 + \omega_{rel})\hat{\mathbf 1} -
/// \Omega_0\sin\alpha_0\hat{\mathbf 3} = \omega\hat{\mathbf 3}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, the lab's angular velocity
/// $R\boldsymbol\omega_b$ against both printed forms, with $\Omega_0$ the run's measured
/// precession rate (heading), $\omega_{rel}$ its measured face-angle rate, $\alpha_0$ and
/// $\hat{\mathbf 1}, \hat{\mathbf 3}$ read from the lab state at the sample, and $\omega$ measured;
/// relative to $|\boldsymbol\omega|$.
pub(super) fn eq37(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        37,
        |run, i| run.snaps[i].omega.norm(),
        "$\\omega$, relative to $|\\omega|$",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed forms of the angular velocity ($\\Omega_0$, $\\omega_{\\mathrm{rel}}$ measured) against the lab's $R \\boldsymbol\\omega_b$, relative to $|\\omega|$",
        w,
        Tolerance::solver(b.rtol))
}
