//! The report's "Friction and contact" section as text: the friction studies' numbers
//! ([`studies::sliding::Studies`]) in plain tables, for the HTML `<pre>` and the LaTeX listing.

use std::fmt::Write;
use studies::sliding::fall::{Fall, FallCase};
use studies::sliding::Studies;

/// Width of the section's lines: headings and notes are wrapped to it (the tables are narrower).
const WIDTH: usize = 100;

/// Appends `text` wrapped at [`WIDTH`], continuation lines indented by four spaces.
fn heading(o: &mut String, text: &str) {
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.len() + 1 + word.len() > WIDTH {
            o.push_str(&line);
            o.push('\n');
            line = "    ".into();
        } else if !line.is_empty() && line != "    " {
            line.push(' ');
        }
        line.push_str(word);
    }
    o.push_str(&line);
    o.push('\n');
}

/// The section's text; the fall study is read against `paper`'s claim.
pub fn text(s: &Studies, paper: &paper::Paper) -> String {
    let mut o = String::new();
    let deg = |x: f64| x.to_degrees();
    // Writing to a String cannot fail.
    heading(
        &mut o,
        "Eq 42 (b > 0): the largest b that rolls, mu a k sin(alpha0) against the sliding model \
         (bisection on runs of 0.02 s)",
    );
    let _ = writeln!(
        o,
        "  alpha0 (rad)    mu   b eq 42 (mm)   b integrated (mm)   eq 42 error"
    );
    for r in &s.slip_onset {
        let _ = writeln!(
            o,
            "  {:>11.2} {:>5.2} {:>14.4} {:>19.4} {:>13.2e}",
            r.alpha0,
            r.mu,
            r.b_eq42 * 1e3,
            r.b_integrated * 1e3,
            r.relative_error
        );
    }
    o.push('\n');
    heading(
        &mut o,
        "Eq 43 (b < 0): the part of eq 30's range b_edge < b < 0 a table holds (largest b/b_edge \
         that rolls), against eq 43's requirement",
    );
    let _ = writeln!(
        o,
        "  alpha0 (rad)    mu   eq 43 needs mu >=   held, integrated   held, exact"
    );
    for r in &s.negative_b {
        let _ = writeln!(
            o,
            "  {:>11.2} {:>5.2} {:>19.3} {:>18.4} {:>13.4}",
            r.alpha0, r.mu, r.mu_eq43, r.beta_integrated, r.beta_exact
        );
    }
    o.push('\n');
    heading(
        &mut o,
        &format!(
        "Sec. 6, radial slippage: steady rolls that eq 42 says must slip, run {} s; the radius \
         of the centre's path over the last second (|b| of the motion it settles in)",
        studies::sliding::spiral::DURATION
        ),
    );
    let _ = writeln!(
        o,
        "  alpha0 (rad)   b0 (mm)    mu   eq 42 |b| (mm)   slid (s)   radius at end (mm)   alpha at end (rad)"
    );
    let mut halted = Vec::new();
    for r in &s.spiral {
        let radius = match r.radius_end {
            Some(x) => format!("{:.3}", x * 1e3),
            None => {
                halted.push(format!(
                    "alpha0 = {}, b0 = {} mm, mu = {}: {}",
                    r.alpha0,
                    r.b0 * 1e3,
                    r.mu,
                    r.ending
                ));
                format!("- (note {})", halted.len())
            }
        };
        let _ = writeln!(
            o,
            "  {:>11.2} {:>9.1} {:>5.2} {:>16.3} {:>10.3}   {:>18} {:>20.3}",
            r.alpha0,
            r.b0 * 1e3,
            r.mu,
            r.b_eq42 * 1e3,
            r.slip_time,
            radius,
            r.alpha_end
        );
    }
    for (i, h) in halted.iter().enumerate() {
        heading(&mut o, &format!("  note {}: {h}", i + 1));
    }
    rising(&mut o, &s.rising);
    o.push('\n');
    heading(
        &mut o,
        "Eqs 80-81's premise: the built-in spin-down (steady b = 0 at 0.15 rad, eq 75 with \
         beta = 2, epsilon = 1.2e-6 s, its unit s^(beta-1)) on Coulomb tables, with eq 75's power as a torque",
    );
    let _ = writeln!(
        o,
        "    mu   first slip: t (s)   alpha (deg)   Omega (rad/s)   min F_z/mg   run ends"
    );
    for c in &s.contact_loss {
        let (t, a, w) = match c.first_slip {
            Some(m) => (
                format!("{:.3}", m.t),
                format!("{:.3}", deg(m.alpha)),
                format!("{:.1}", m.omega),
            ),
            None => ("never".into(), "-".into(), "-".into()),
        };
        let ends = match (c.first_slip, c.lift_off) {
            (Some(_), _) => "at the first slip".to_string(),
            (None, Some(m)) => format!("contact lost at {:.3} s", m.t),
            (None, None) => format!(
                "alpha {:.0e} rad at {:.3} s, never lifted",
                c.end.alpha, c.end.t
            ),
        };
        let _ = writeln!(
            o,
            "  {:>4.2} {:>19} {:>13} {:>15} {:>12.3}   {ends}",
            c.mu, t, a, w, c.min_normal_rolling
        );
    }
    fall(&mut o, &s.fall, paper);
    mechanisms(&mut o, &s.mechanisms);
    o
}

/// The claim the fall study answers (paper/claims.yaml).
const FALL_CLAIM: &str = "positive-b-unstable-large-tilt";

/// The fall claim's printed tilt (deg) and its reading `within` (a relative distance), from
/// `paper`'s claims; `None` if the claim or that reading is missing.
pub(crate) fn fall_claim(paper: &paper::Paper) -> Option<(f64, f64)> {
    let c = paper.claims.iter().find(|c| c.id == FALL_CLAIM)?;
    Some((c.claimed_value?, c.rule.as_ref()?.within?))
}

/// Sec. 10: the rising of a disk launched spinning about a nearly vertical diameter, per
/// contact.
fn rising(o: &mut String, ri: &studies::sliding::rising::Rising) {
    o.push('\n');
    heading(
        o,
        &format!(
            "Sec. 10, rising: launched at {:.0} deg turning about the vertical at {:.1} rad/s \
         (1.5 x sqrt(g/(a k))), centre at rest, contact sliding at {:.3} m/s; lasting gain of \
         tilt = lowest tilt in the second half of {} s minus the launch tilt",
            ri.launch_tilt_deg,
            ri.launch_rate,
            ri.launch_slip,
            studies::sliding::rising::DURATION
        ),
    );
    let _ = writeln!(
        o,
        "  contact              mu   gain (deg)   highest tilt (deg)   slid (s)"
    );
    for c in &ri.cases {
        let slid = if c.mu == 0.0 {
            "-".to_string()
        } else {
            format!("{:.3}", c.slip_time.max(0.0))
        };
        let _ = writeln!(
            o,
            "  {:<18} {:>4.2} {:>12.3} {:>20.2} {:>10}",
            c.contact, c.mu, c.rise_deg, c.highest_deg, slid
        );
    }
}

/// Sec. 7 and the summary: the fall from unstable steady motion at large tilt, the tilt it
/// falls to against the claim's "about 60 degrees", rolling and on Coulomb tables.
fn fall(o: &mut String, f: &Fall, paper: &paper::Paper) {
    use studies::sliding::fall::{DURATION, LEFT, NUDGE};
    o.push('\n');
    let Some((claimed, within)) = fall_claim(paper) else {
        heading(
            o,
            &format!("The fall study: claim `{FALL_CLAIM}` has no `within` reading in claims.yaml"),
        );
        return;
    };
    let (lo, hi) = (claimed * (1.0 - within), claimed * (1.0 + within));
    heading(
        o,
        &format!(
            "Sec. 7 and the summary, \"falls over quickly into a rolling motion with alpha0 below \
             about {:.0} deg\": steady rolls in the unstable band of b (linearized eqs 23-25), b at \
             the band's middle, tilt nudged down {NUDGE} rad, run {DURATION} s rolling (eqs 23-25) \
             and on Coulomb tables. Falls to: the first minimum of the tilt once it is {LEFT:.0} \
             deg below alpha0; 'about' read as {lo:.0} to {hi:.0} deg (claims.yaml). 1/lambda: \
             the instability's e-folding time; mu steady: the friction the steady start needs",
            claimed
        ),
    );
    fall_tables(o, f, claimed, (lo, hi));
    fall_verdict(o, f, claimed, (lo, hi));
}

/// The fall study's tables: the unstable bands, each run, and the tilt fallen to across each
/// band; `(lo, hi)` is the claim's reading.
fn fall_tables(o: &mut String, f: &Fall, claimed: f64, (lo, hi): (f64, f64)) {
    use studies::sliding::fall::DURATION;
    let holds = |c: &FallCase| c.fell_to_deg.map(|x| (lo..=hi).contains(&x));
    let _ = writeln!(
        o,
        "  alpha0 (deg)   unstable b/a     start b/a   1/lambda (s)   2 pi/Omega0 (s)   mu steady"
    );
    for b in &f.bands {
        let _ = writeln!(
            o,
            "  {:>12.0}   {:>5.3}-{:<7.3} {:>10.3} {:>14.3} {:>17.3} {:>11.3}",
            b.alpha0_deg,
            b.lower,
            b.upper,
            b.start,
            1.0 / b.growth,
            2.0 * std::f64::consts::PI / b.precession.abs(),
            b.mu_needed
        );
    }
    let _ = writeln!(
        o,
        "  alpha0 (deg)  contact     mu   falls to (deg)   t (s)   periods   slid   lifted   lowest (deg)   at {DURATION} s (deg)   about {:.0}",
        claimed
    );
    let yes = |x: bool| if x { "yes" } else { "no" };
    for c in &f.cases {
        let opt = |x: Option<f64>, p: usize| x.map_or("-".into(), |v| format!("{v:.p$}"));
        let _ = writeln!(
            o,
            "  {:>12.0}  {:<9} {:>4} {:>16} {:>7} {:>9} {:>6} {:>8} {:>14.2} {:>18.2}   {}",
            c.alpha0_deg,
            if c.mu.is_some() { "Coulomb" } else { "rolling" },
            opt(c.mu, 1),
            opt(c.fell_to_deg, 2),
            opt(c.fall_time, 3),
            opt(c.fall_periods, 2),
            yes(c.slipped),
            yes(c.lifted),
            c.lowest_deg,
            c.end_deg,
            holds(c).map_or("-", yes)
        );
    }
    let fractions: Vec<String> = studies::sliding::fall::ACROSS
        .iter()
        .map(|x| format!("{x:.2}"))
        .collect();
    heading(
        o,
        &format!(
            "  Rolling across the band: the tilt it falls to (deg), b/a in brackets, at {} of the \
             band's width from its lower edge",
            fractions.join(", ")
        ),
    );
    for b in &f.bands {
        let _ = write!(o, "  {:>12.0}  ", b.alpha0_deg);
        for c in f.across.iter().filter(|c| c.alpha0_deg == b.alpha0_deg) {
            let to = c.fell_to_deg.map_or("-".into(), |x| format!("{x:.1}"));
            let _ = write!(o, " {:>6} ({:.2})", to, c.b_over_a);
        }
        o.push('\n');
    }
}

/// The fall study's verdict on the claim read as `(lo, hi)`.
fn fall_verdict(o: &mut String, f: &Fall, claimed: f64, (lo, hi): (f64, f64)) {
    use studies::sliding::fall::{DURATION, LEFT};
    let holds = |c: &FallCase| c.fell_to_deg.map(|x| (lo..=hi).contains(&x));
    let spread = |pick: fn(f64, f64) -> f64, start: f64| {
        f.across
            .iter()
            .filter_map(|c| c.fell_to_deg)
            .fold(start, pick)
    };
    let held = f.cases.iter().filter(|c| holds(c) == Some(true)).count();
    let below = f
        .cases
        .iter()
        .filter(|c| c.fell_to_deg.is_some_and(|x| x <= hi))
        .count();
    let slowest = f
        .cases
        .iter()
        .filter_map(|c| c.fall_periods)
        .fold(0.0, f64::max);
    let miss = |c: &FallCase| {
        c.fell_to_deg.map_or(String::new(), |x| {
            if x > hi {
                format!("{:.1} deg above", x - hi)
            } else if x < lo {
                format!("{:.1} deg below", lo - x)
            } else {
                "inside".into()
            }
        })
    };
    let rolling: Vec<String> = f
        .cases
        .iter()
        .filter(|c| c.mu.is_none())
        .map(|c| {
            format!(
                "from {:.0} deg to {:.1} ({}) in {:.2} periods",
                c.alpha0_deg,
                c.fell_to_deg.unwrap_or(f64::NAN),
                miss(c),
                c.fall_periods.unwrap_or(f64::NAN)
            )
        })
        .collect();
    let slid: Vec<String> = f
        .cases
        .iter()
        .filter(|c| c.slipped)
        .map(|c| {
            format!(
                "{:.0} deg, mu {}: to {:.1} ({}), {:.1} at {DURATION} s",
                c.alpha0_deg,
                c.mu.unwrap_or(f64::NAN),
                c.fell_to_deg.unwrap_or(f64::NAN),
                miss(c),
                c.end_deg
            )
        })
        .collect();
    heading(
        o,
        &format!(
            "Verdict: the disk does fall quickly (within {slowest:.2} precession periods), but \
             'about {claimed:.0} deg' ({lo:.0}-{hi:.0}) holds in {held} of {} runs; read as the \
             paper's LaTeX writes it, 'alpha0 \\lsim {claimed:.0} deg' (at most {hi:.0}), in \
             {below}. Rolling, and on every table that never slides (the same numbers): {}; with \
             no dissipation it then swings back up toward alpha0 (the tilt at the end). Where \
             the contact slides during the fall: {}. Across the bands the rolling disk falls \
             to anywhere from {:.1} to {:.1} deg: the tilt depends on the start (alpha0 and b), \
             not on a tilt near {claimed:.0} deg; a dash: it did not fall {LEFT:.0} deg within \
             {DURATION} s.",
            f.cases.len(),
            rolling.join("; "),
            if slid.is_empty() {
                "none".into()
            } else {
                slid.join("; ")
            },
            spread(f64::min, f64::INFINITY),
            spread(f64::max, f64::NEG_INFINITY)
        ),
    );
}

/// The mechanisms side by side (beyond the paper): each one's spin-down fitted as the
/// experiment would, and where air would take over.
fn mechanisms(o: &mut String, m: &experiment::mechanisms::Mechanisms) {
    o.push('\n');
    heading(
        o,
        &format!(
            "Dissipation mechanisms side by side (beyond the paper): each alone, calibrated to \
             supply what the paper's record needs at Omega = {:.0} rad/s (eq 79 with beta = {}, \
             through eq 26's energy), spins the toy disk down from steady b = 0 at 80 rad/s; \
             the last 10 s, cut into turns, are fitted by the experiment's eq 84 and its \
             comparison of laws",
            m.omega_cal, m.data_beta
        ),
    );
    let _ = writeln!(
        o,
        "  {:<30}{:>12}{:>9}{:>17}{:>7}  Omega (rad/s)",
        "mechanism", "coefficient", "beta", "beta fitted", "turns"
    );
    for r in &m.spin_downs {
        let fitted = match (r.beta, &r.refused) {
            (Some((b, e)), None) => crate::number::measured(b, e),
            (_, Some(_)) => "refused".into(),
            (None, None) => "-".into(),
        };
        let unit = if r.unit == "1" {
            String::new()
        } else {
            format!(" {}", r.unit)
        };
        let _ = writeln!(
            o,
            "  {:<30}{:>12}{:>9.1}{:>17}{:>7}  {:>4.0}-{:.0}",
            r.mechanism,
            format!("{:.2e}{unit}", r.coefficient),
            r.exponent,
            fitted,
            r.fitted,
            r.omega_range.0,
            r.omega_range.1
        );
    }
    for r in &m.spin_downs {
        match (&r.refused, &r.best_law) {
            (Some(why), _) => heading(o, &format!("  {}: refused: {why}", r.mechanism)),
            (None, Some(best)) => heading(
                o,
                &format!(
                    "  {}: the model choice takes {best}; beta = 2's BIC is {:.0} above the least",
                    r.mechanism,
                    r.delta_bic_beta_two.unwrap_or(f64::NAN)
                ),
            ),
            (None, None) => {}
        }
    }
    let two: Vec<&str> = m
        .spin_downs
        .iter()
        .filter(|r| r.gives(2.0))
        .map(|r| r.mechanism.as_str())
        .collect();
    let air: Vec<String> = m
        .air_over_need
        .iter()
        .map(|a| {
            format!(
                "{:.0} rad/s: layer {:.1}, film {:.2}",
                a.omega, a.layer, a.film
            )
        })
        .collect();
    heading(
        o,
        &format!(
            "Gives the paper's beta = 2 (within 3 sigma or 0.15): {}. Slip friction takes \
             next to nothing here: with b = 0 the centre of mass barely moves, so the table's \
             push is nearly vertical and the disk rolls without slipping until late in the \
             spin-down (the table above). Air with its own viscosity, over what the record needs: {} (the \
             layer's factor of order one set to 1; the film holds only above {:.0} rad/s, \
             where the gap is thinner than the viscous layer).",
            if two.is_empty() {
                "none".into()
            } else {
                two.join(", ")
            },
            air.join("; "),
            m.film_valid_above
        ),
    );
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_fall_claim_and_its_reading_are_found() {
        let paper = paper::Paper::built_in_shared();
        assert_eq!(super::fall_claim(paper), Some((60.0, 0.05)));
    }
}
