//! Evaluating a parsed expression: over `f64`, or over dual numbers for exact derivatives.
//!
//! A value is a scalar, a 3-vector or a 3x3 tensor (the inertia tensor of eqs 19 and 26), in
//! whatever frame the check binds its vectors in (the checks use lab components).

use super::expr::{Expr, Func, Op, Symbol};
use nalgebra::{Matrix3, RealField, Vector3};

/// A value of an expression.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value<T: RealField + Copy> {
    /// A number.
    Scalar(T),
    /// A vector.
    Vector(Vector3<T>),
    /// A tensor (matrix).
    Tensor(Matrix3<T>),
}

/// Why an expression could not be evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EvalError {
    /// A symbol the check does not provide.
    #[error("the symbol {0} has no value here")]
    Unbound(String),
    /// An operation on values of the wrong kinds (a vector to a power, a cross product of
    /// scalars, a sum of a scalar and a vector).
    #[error("{0}")]
    Kind(String),
}

impl<T: RealField + Copy> Value<T> {
    /// The scalar, or an error naming what was found.
    pub fn scalar(self) -> Result<T, EvalError> {
        match self {
            Value::Scalar(x) => Ok(x),
            other => Err(EvalError::Kind(format!(
                "a scalar was expected, found a {}",
                other.kind()
            ))),
        }
    }

    /// The vector, or an error naming what was found.
    pub fn vector(self) -> Result<Vector3<T>, EvalError> {
        match self {
            Value::Vector(v) => Ok(v),
            // A printed `= 0` compares a vector with the zero vector.
            Value::Scalar(x) if x == T::zero() => Ok(Vector3::zeros()),
            other => Err(EvalError::Kind(format!(
                "a vector was expected, found a {}",
                other.kind()
            ))),
        }
    }

    /// "scalar", "vector" or "tensor".
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Scalar(_) => "scalar",
            Value::Vector(_) => "vector",
            Value::Tensor(_) => "tensor",
        }
    }
}

fn kind_error<T: RealField + Copy>(op: &str, a: &Value<T>, b: &Value<T>) -> EvalError {
    EvalError::Kind(format!("{op} of a {} and a {}", a.kind(), b.kind()))
}

fn constant<T: RealField + Copy>(x: f64) -> T {
    nalgebra::convert(x)
}

/// Evaluates `e`, asking `lookup` for the value of each symbol.
pub fn eval<T: RealField + Copy>(
    e: &Expr,
    lookup: &dyn Fn(&Symbol) -> Result<Value<T>, EvalError>,
) -> Result<Value<T>, EvalError> {
    use Value::{Scalar as S, Tensor as M, Vector as V};
    Ok(match e {
        Expr::Num(x) => S(constant(*x)),
        Expr::Pi => S(T::pi()),
        Expr::Sym(s) => lookup(s)?,
        Expr::Neg(a) => match eval(a, lookup)? {
            S(x) => S(-x),
            V(v) => V(-v),
            M(m) => M(-m),
        },
        Expr::Call(f, a) => {
            let x = eval(a, lookup)?;
            if let (Func::Abs, V(v)) = (f, x) {
                return Ok(S(v.norm()));
            }
            let x = x
                .scalar()
                .map_err(|_| EvalError::Kind(format!("{} of a {}", f.latex(), x.kind())))?;
            S(match f {
                Func::Sin => x.sin(),
                Func::Cos => x.cos(),
                Func::Tan => x.tan(),
                Func::Cot => x.tan().recip(),
                Func::Sqrt => x.sqrt(),
                Func::Abs => x.abs(),
            })
        }
        Expr::Bin(Op::Pow, a, n) if integer(n).is_some() => {
            let x = eval(a, lookup)?.scalar()?;
            S(powi(x, integer(n).unwrap_or(1)))
        }
        Expr::Bin(op, a, b) => {
            let (a, b) = (eval(a, lookup)?, eval(b, lookup)?);
            match (op, a, b) {
                (Op::Add, S(x), S(y)) => S(x + y),
                (Op::Add, V(x), V(y)) => V(x + y),
                (Op::Add, M(x), M(y)) => M(x + y),
                (Op::Sub, S(x), S(y)) => S(x - y),
                (Op::Sub, V(x), V(y)) => V(x - y),
                (Op::Sub, M(x), M(y)) => M(x - y),
                (Op::Mul, S(x), S(y)) => S(x * y),
                (Op::Mul, S(x), V(v)) | (Op::Mul, V(v), S(x)) => V(v * x),
                (Op::Mul, S(x), M(m)) | (Op::Mul, M(m), S(x)) => M(m * x),
                (Op::Div, S(x), S(y)) => S(x / y),
                (Op::Div, V(v), S(y)) => V(v / y),
                (Op::Dot, V(x), V(y)) => S(x.dot(&y)),
                (Op::Dot, M(m), V(v)) => V(m * v),
                (Op::Dot, V(v), M(m)) => V(m.transpose() * v),
                (Op::Cross, V(x), V(y)) => V(x.cross(&y)),
                (Op::Pow, S(x), S(y)) => S(x.powf(y)),
                (op, a, b) => return Err(kind_error(&format!("{op:?}"), &a, &b)),
            }
        }
    })
}

/// A small integer exponent as printed (`^2`, `^{-1}`), taken exactly.
fn integer(e: &Expr) -> Option<i32> {
    let n = match e {
        Expr::Num(x) => *x,
        Expr::Neg(a) => match a.as_ref() {
            Expr::Num(x) => -*x,
            _ => return None,
        },
        _ => return None,
    };
    (n.fract() == 0.0 && n.abs() <= 8.0).then_some(n as i32)
}

/// $x^n$ by repeated products, so that a negative base squared stays real and dual parts stay
/// exact.
fn powi<T: RealField + Copy>(x: T, n: i32) -> T {
    let mut r = T::one();
    for _ in 0..n.unsigned_abs() {
        r *= x;
    }
    if n < 0 {
        r.recip()
    } else {
        r
    }
}
