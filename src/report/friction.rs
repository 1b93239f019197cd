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
    o
}
