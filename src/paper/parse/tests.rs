//! Tests of the reader.

use super::*;

fn one(latex: &str) -> String {
    let (chains, _) = parse(latex).unwrap_or_else(|e| panic!("{latex}: {e:?}"));
    chains
        .iter()
        .map(|c| {
            let mut s = c.sides[0].to_latex();
            for (r, side) in c.rels.iter().zip(&c.sides[1..]) {
                s += &format!(" {} {}", r.latex(), side.to_latex());
            }
            s
        })
        .collect::<Vec<_>>()
        .join(" ; ")
}

#[test]
fn the_physicists_slash() {
    assert_eq!(
        one(r"\frac{5 g / \epsilon (\beta + 2) a k}{t_0 - t}"),
        "((5 g)/(epsilon (beta + 2) a k))/((t_0 - t))"
    );
    assert_eq!(one(r"x^{1 / 2 (\beta + 1)}"), "(x)^{(1)/(2 (beta + 1))}");
}

#[test]
fn function_arguments_and_powers() {
    assert_eq!(one(r"\cos\varpi t"), r"\cos(varpi t)");
    assert_eq!(
        one(r"\Omega \sin\alpha \hat{\mathbf{3}}"),
        r"Omega \sin(alpha) hat:bf:3"
    );
    assert_eq!(one(r"\cos^2\alpha_0"), r"(\cos(alpha_0))^{2}");
    assert_eq!(one(r"\omega^2_{10}"), "(omega_10)^{2}");
    assert_eq!(
        one(r"\sin\alpha_0 \cos\alpha_0"),
        r"\sin(alpha_0) \cos(alpha_0)"
    );
}

#[test]
fn derivatives_crosses_and_chains() {
    assert_eq!(
        one(r"\frac{d\hat{\mathbf{1}}}{dt} = \vec{\omega}_{123} \times \hat{\mathbf{1}}"),
        "d/dt:hat:bf:1 = (vec:omega_123 \\times hat:bf:1)"
    );
    assert_eq!(
        one(r"\frac{d^2 \mathbf{r}_{\mathrm{cm}}}{dt^2}"),
        "d2/dt2:bf:r_cm"
    );
    assert_eq!(
        one(r"a \hat{\mathbf{3}} \times m g \hat{\mathbf{z}}"),
        "(a hat:bf:3 \\times m g hat:bf:z)"
    );
    assert_eq!(
        one(r"I_{11} = 2 k m a^2, \qquad I_{22} = k m a^2 = I_{33}"),
        "I_11 = 2 k m (a)^{2} ; I_22 = k m (a)^{2} = I_33"
    );
    assert_eq!(one(r"\dot{x}_A"), "dot:x_A");
    assert_eq!(one(r"\left| b \right| \geq 0"), r"\abs(b) \geq 0");
}

#[test]
fn errors_name_the_column() {
    let e = parse(r"\alpha = \frac{g}{a").unwrap_err();
    assert_eq!(e.column, 20, "{e:?}");
    let e = parse(r"\alpha = \foo").unwrap_err();
    assert_eq!(e.column, 10, "{e:?}");
    assert!(e.message.contains("\\foo"), "{e:?}");
    let e = parse(r"a = b )").unwrap_err();
    assert_eq!(e.column, 7, "{e:?}");
}
