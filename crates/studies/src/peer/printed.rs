//! `rolling-disk peer compare`'s text: the largest differences, the rows whose modes differ
//! (said as such when they differ throughout), the breaks of the peer's clock, and the switches
//! paired by direction and time with those left over.

use super::compare::PeerComparison;
use super::pairing::PeerSwitch;
use std::fmt;

fn direction(to_rolling: bool) -> &'static str {
    if to_rolling {
        "to rolling"
    } else {
        "to sliding"
    }
}

fn interval(p: &PeerSwitch) -> String {
    format!("{:.6} to {:.6} s", p.within.0, p.within.1)
}

impl fmt::Display for PeerComparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "compared {} rows up to t = {:.6} s (peer record ends at {:.6} s; this tool's run at {:.6} s: {})",
            self.rows, self.until, self.peer_end, self.tool_end.0, self.tool_end.1
        )?;
        for b in &self.clock {
            if b.offset != 0.0 {
                writeln!(
                    f,
                    "the peer's clock: from its row labelled {:.6} s on ({}), its state is {:.3e} s later than its label; rows compared at the time of their state",
                    b.label,
                    if b.relock {
                        "a relock, whose state it keeps from the end of its integration step"
                    } else {
                        "a restart at t = 0 with its clock set back"
                    },
                    b.offset
                )?;
            }
        }
        writeln!(f, "largest differences (this tool - peer):")?;
        for (name, l, unit) in [
            ("tilt alpha", self.tilt, "rad"),
            ("spin", self.spin, "rad/s"),
            ("heading", self.heading, "rad"),
            ("centre", self.centre, "m"),
            ("Fz/mg", self.normal, ""),
            ("|Ft|/mg", self.friction, ""),
            ("slip speed", self.slip, "m/s"),
            ("energy", self.energy, "J"),
        ] {
            writeln!(
                f,
                "  {name:<11} {:.3e} {unit:<5} at t = {:.6} s",
                l.value, l.at
            )?;
        }
        let m = &self.modes;
        if m.whole_run() {
            writeln!(
                f,
                "  modes: they differ in every one of the {} rows compared after t = 0: the two runs are in different modes throughout",
                m.of
            )?;
        } else if m.rows > 0 {
            writeln!(
                f,
                "  modes: they differ in {} of {} rows, between t = {:.6} and {:.6} s",
                m.rows, m.of, m.between.0, m.between.1
            )?;
        } else {
            writeln!(f, "  modes: the same in all {} rows after t = 0", m.of)?;
        }
        if m.peer_creeps.0 > 0 {
            writeln!(
                f,
                "    the peer slides where this tool rolls in {} rows, slipping at up to {:.3e} m/s (its regularized friction creeps instead of relocking)",
                m.peer_creeps.0, m.peer_creeps.1
            )?;
        }
        let p = &self.pairing;
        write!(
            f,
            "  rolling/sliding changes: {} in the peer, {} here; ",
            self.switch_counts.0, self.switch_counts.1
        )?;
        match p.largest_outside() {
            None => writeln!(f, "none paired")?,
            Some(d) => writeln!(
                f,
                "{} paired by direction and time, the largest outside the peer's interval {:.3e} s",
                p.paired.len(),
                d
            )?,
        }
        for q in &p.paired {
            writeln!(
                f,
                "    {}: peer between {}, here {:.6} s",
                direction(q.peer.to_rolling),
                interval(&q.peer),
                q.tool
            )?;
        }
        for q in &p.peer_only {
            writeln!(
                f,
                "    {}: peer between {}, none here",
                direction(q.to_rolling),
                interval(q)
            )?;
        }
        for (to_rolling, t) in &p.tool_only {
            writeln!(
                f,
                "    {}: here {t:.6} s, none in the peer",
                direction(*to_rolling)
            )?;
        }
        Ok(())
    }
}
