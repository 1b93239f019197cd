//! The report's "Friction and contact" section as text: the friction studies' numbers
//! ([`crate::friction::Studies`]) in plain tables, for the HTML `<pre>` and the LaTeX listing.

use crate::friction::Studies;
use std::fmt::Write;

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

/// The section's text.
pub fn text(s: &Studies) -> String {
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
        crate::friction::spiral::DURATION
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
    let ri = &s.rising;
    o.push('\n');
    heading(
        &mut o,
        &format!(
            "Sec. 10, rising: launched at {:.0} deg turning about the vertical at {:.1} rad/s \
         (1.5 x sqrt(g/(a k))), centre at rest, contact sliding at {:.3} m/s; lasting gain of \
         tilt = lowest tilt in the second half of {} s minus the launch tilt",
            ri.launch_tilt_deg,
            ri.launch_rate,
            ri.launch_slip,
            crate::friction::rising::DURATION
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
    o.push('\n');
    heading(
        &mut o,
        "Eqs 80-81's premise: the built-in spin-down (steady b = 0 at 0.15 rad, eq 75 with \
         beta = 2, epsilon = 1.2e-6 s^2) on Coulomb tables, with eq 75's power as a torque",
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
    mechanisms(&mut o, &s.mechanisms);
    o
}

/// The mechanisms side by side (beyond the paper): each one's spin-down fitted as the
/// experiment would, and where air would take over.
fn mechanisms(o: &mut String, m: &crate::friction::mechanisms::Mechanisms) {
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
            (Some((b, e)), None) => format!("{b:.3} +- {e:.3}"),
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
                    "  {}: BIC prefers {best}; beta = 2 is {:.0} higher",
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
