//! Builds a scene's model with only the states it needs and hands it to a generic visitor: the
//! one place that turns a [`Scene`] into a concrete model with a concrete number of states, used
//! by [`crate::run::run`] and by the speed/accuracy measurements.

use crate::model::adiabatic::Adiabatic;
use crate::model::frictionless::Frictionless;
use crate::model::lab_frame::{Contact, LabFrame};
use crate::model::rolling::Rolling;
use crate::model::sliding::{Friction, Sliding};
use crate::model::{Layout, Model, Quantity};
use crate::scene::{ModelKind, Scene};
use crate::solve::{onto_level, Event, Problem, Projection, State};

/// Something done with a scene's model, whatever its number of states.
pub trait Visit {
    /// What it returns.
    type Out;
    /// Does it with `model`.
    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out;
}

/// The sliding model a validated scene asks for, with eq 75's law as a drag torque when the
/// scene gives `dissipation`.
pub fn sliding_model(scene: &Scene) -> Sliding {
    let friction = scene.friction.unwrap_or(Friction {
        mu: 0.0,
        restitution: 0.0,
    });
    let mut m = Sliding::new(scene.disk, friction).with_slip(scene.slip);
    if let Some(law) = scene.dissipation {
        m = m.with_drag(law);
    }
    m.stop_at_lift_off = scene.stop.lift_off;
    m.toy = scene.toy;
    m
}

/// Calls `v` with the scene's model.
pub fn dispatch<V: Visit>(scene: &Scene, v: V) -> V::Out {
    let extras = scene.extras();
    let d = scene.disk;
    macro_rules! rolling {
        ($($n:literal),*) => {
            match Layout::new(4, extras).len {
                $($n => v.visit(
                    &Rolling::<$n>::new(d, extras, scene.dissipation)
                        .with_mechanisms(&scene.mechanisms),
                    scene,
                ),)*
                n => unreachable!("a rolling layout has 4 to 8 states, not {n}"),
            }
        };
    }
    macro_rules! frictionless {
        ($($n:literal),*) => {
            match Frictionless::<3>::states(extras) {
                $($n => v.visit(&Frictionless::<$n>::new(d, scene.start.spin, extras), scene),)*
                n => unreachable!("a frictionless layout has 3 to 5 states, not {n}"),
            }
        };
    }
    match scene.model {
        ModelKind::Rolling | ModelKind::Dissipative => rolling!(4, 5, 6, 7, 8),
        ModelKind::Frictionless => frictionless!(3, 4, 5),
        ModelKind::Adiabatic => {
            let law = scene.dissipation.expect("validated: adiabatic has a law");
            v.visit(&Adiabatic::new(d, law), scene)
        }
        ModelKind::LabFrame => v.visit(&LabFrame::new(d, Contact::Rolling), scene),
        ModelKind::LabFrameFrictionless => v.visit(&LabFrame::new(d, Contact::Frictionless), scene),
        // The sliding model switches between flows; what is generic over one model (the cost
        // of a right-hand side, work-precision) sees the flow of the mode it starts in. Runs go
        // through `crate::run::sliding::run`.
        ModelKind::Sliding => {
            let model = sliding_model(scene);
            let (mode, _) = model.enter_contact(&model.start_state(&scene.start));
            v.visit(
                &crate::model::sliding::Flow {
                    model: &model,
                    mode,
                },
                scene,
            )
        }
    }
}

/// The scene's problem from `t0` = 0 and state `y0` to `t_end`, with its stop events.
pub fn problem<'a, M: Model<N>, const N: usize>(
    model: &'a M,
    scene: &Scene,
    y0: State<N>,
    t_end: f64,
) -> Problem<'a, M, N> {
    // The paper's alpha lies in (0, pi): at 0 or pi the disk lies flat on the table and the
    // equations of motion (eq 25 divides by sin alpha) no longer describe it.
    let mut p = Problem::new(model, 0.0, y0, t_end)
        .stop_when(Event::new(
            "the disk fell flat on the table (alpha reached 0)",
            move |y: &State<N>| model.motion(y).alpha,
        ))
        .stop_when(Event::new(
            "the disk fell flat on the table (alpha reached pi)",
            move |y: &State<N>| std::f64::consts::PI - model.motion(y).alpha,
        ));
    if scene.projection == Some(Projection::Energy) {
        let e0 = model.energy(&y0);
        p.project = Some(Box::new(move |y: &mut State<N>| {
            onto_level(|y| model.energy(y), e0, y)
        }));
    }
    if let Some(bound) = scene.stop.alpha_below {
        p = p.stop_when(Event::new(
            format!("alpha fell below {bound} rad"),
            move |y: &State<N>| model.motion(y).alpha - bound,
        ));
    }
    if scene.stop.lift_off {
        p = p.stop_when(Event::new(
            "the disk left the table (F_z = 0)",
            |y: &State<N>| {
                let mut f = Vec::with_capacity(1);
                model.record(y, Quantity::NormalForce, &mut f);
                f[0]
            },
        ));
    }
    p
}
