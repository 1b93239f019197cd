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

#[test]
fn other_notations_read_the_same() {
    let same =
        |a: &str, b: &str| assert_eq!(parse(a).unwrap().0, parse(b).unwrap().0, "{a} vs {b}");
    // Between scalar factors, `\cdot` and `\times` are juxtaposition, left to right.
    same(
        r"\frac{g}{k \cdot a \sin(\alpha_{0})}",
        r"\frac{g}{k a \sin\alpha_0}",
    );
    same(
        r"a \hat{\mathbf{3}} \times m \cdot g \hat{\mathbf{z}}",
        r"a \hat{\mathbf{3}} \times m g \hat{\mathbf{z}}",
    );
    same(r"g \cdot 1", "g 1");
    same(r"2 \times k", "2 k");
    same(r"\dfrac{a}{b} + \tfrac{a}{b}", r"\frac{a}{b} + \frac{a}{b}");
    same(r"\bigl( a + b \bigr) \Big[ c \Big]", "(a + b) (c)");
    same(r"a \, b \; c \! d \ e ~ f \quad g", "a b c d e f g");
    same(r"x = a, \quad y = b.", "x = a, y = b");
    same(r"x = a; y = b;", "x = a, y = b");
    same(r"x = 0.5.", "x = 0.5");
    // Between vectors, the scalar and the vector products.
    let (c, _) = parse(r"\mathbf{a} \times \hat{\mathbf{3}} \cdot \vec{\omega}").unwrap();
    assert_eq!(
        c[0].sides[0].to_latex(),
        r"((bf:a \times hat:bf:3) \cdot vec:omega)"
    );
}

#[test]
fn what_cannot_be_evaluated_is_refused_where_it_is_written() {
    let e = parse(r"x = a + \hat{\mathbf{1}}").unwrap_err();
    assert_eq!(e.column, 7, "{e:?}");
    assert!(e.message.contains("a scalar and a vector"), "{e:?}");
    let e = parse(r"x = \mathbf{v}^2").unwrap_err();
    assert!(e.message.contains("a vector to a power"), "{e:?}");
    let e = parse(r"x = \sin(\mathbf{a})").unwrap_err();
    assert!(e.message.contains("of a vector"), "{e:?}");
    let e = parse(r"x = a \div b").unwrap_err();
    assert!(
        e.message.contains(r"\frac{numerator}{denominator}"),
        "{e:?}"
    );
    let e = parse("x = a * b").unwrap_err();
    assert!(e.message.contains(r"\cdot"), "{e:?}");
    let e = parse("x = a. b").unwrap_err();
    assert!(e.message.contains("after the full stop"), "{e:?}");
}

#[test]
fn nesting_and_size_are_limited_before_recursing() {
    let deep = format!(
        "{}a{}",
        "(".repeat(MAX_DEPTH + 5),
        ")".repeat(MAX_DEPTH + 5)
    );
    let e = parse(&deep).unwrap_err();
    assert_eq!(e.column, MAX_DEPTH + 1, "{e:?}");
    let fracs = format!("{}1{}", r"\frac{1}{".repeat(3000), "}".repeat(3000));
    assert!(parse(&fracs).unwrap_err().message.contains("characters"));
    let long = vec!["a"; 300].join(" + ");
    assert!(parse(&long)
        .unwrap_err()
        .message
        .contains("operations deep"));
    let ok = format!("{}a{}", "(".repeat(100), ")".repeat(100));
    assert!(parse(&ok).is_ok());
}

/// Each hint the reader gives, applied as it says, makes the text read: `(refused, a phrase of
/// its hint, the text with the hint's edit applied)`.
#[test]
fn every_hint_applied_reads() {
    for (bad, says, fixed) in [
        (r"x = b \over c", "in braces", r"x = {b \over c}"),
        (r"x = b \over c", r"\frac{numerator}", r"x = \frac{b}{c}"),
        (r"x = b \div c", r"\frac{numerator}", r"x = \frac{b}{c}"),
        (r"x \lsim b", r"\le", r"x \le b"),
        (r"x \neq b", r"\approx", r"x \approx b"),
        (r"x = k \ast m", "juxtaposition", r"x = k m"),
        (r"x = k * m", r"\cdot", r"x = k \cdot m"),
        (
            r"x = a \quad \text for b > 0",
            "in braces",
            r"x = a \quad \text{for b > 0}",
        ),
        (
            r"x = \mathbf{v}^2",
            r"\mathbf{v} \cdot \mathbf{v}",
            r"x = \mathbf{v} \cdot \mathbf{v}",
        ),
        (
            r"x = \mathbf{v}^2",
            r"\left| \mathbf{v} \right|^2",
            r"x = \left| \mathbf{v} \right|^2",
        ),
        (r"x = a^23", "with braces", r"x = a^{23}"),
        (
            r"x = a \text{ and } = b",
            "write the quantity again",
            r"x = a \text{ and } x = b",
        ),
        (
            r"x = \frac{d}{dt} \dot\Omega",
            r"\frac{d^2 X}{dt^2}",
            r"x = \frac{d^2 \Omega}{dt^2}",
        ),
        (
            r"x = \frac{d}{dt} (a \Omega)",
            r"\frac{d X}{dt}",
            r"x = a \frac{d \Omega}{dt}",
        ),
        (r"x = d\Omega^2/dt", "(dX/dt)^2", r"x = (d\Omega/dt)^2"),
        (
            r"\begin{array}{l} x = a \\ y = b \end{array}",
            "a relation of its own",
            r"x = a \\ y = b",
        ),
        (
            r"f = \begin{cases} 1 & \begin{cases} 2 & b > 0 \end{cases} \end{cases}",
            r"\text{for } b > 0",
            r"f = 1, \qquad f = 2 \quad \text{for } b > 0",
        ),
        (
            r"f = \begin{cases} 1 & b > 0",
            r"add \end{cases}",
            r"f = \begin{cases} 1 & b > 0 \end{cases}",
        ),
        (r"f = 1 & b > 0 \end{cases}", "remove it", r"f = 1 & b > 0"),
        (
            r"\begin{cases} 1 & b > 0 \end{cases}",
            "the quantity and the relation",
            r"f = \begin{cases} 1 & b > 0 \end{cases}",
        ),
        (
            r"f = \begin{cases} 1 & b \\ 2 & b < 0 \end{cases}",
            r"\text{for } b > 0",
            r"f = \begin{cases} 1 & \text{for } b > 0 \\ 2 & b < 0 \end{cases}",
        ),
        (
            r"f = \begin{cases} & b > 0 \end{cases}",
            "1 & b > 0",
            r"f = \begin{cases} 1 & b > 0 \end{cases}",
        ),
    ] {
        let e = parse(bad).expect_err(bad);
        assert!(e.message.contains(says), "{bad}: {}", e.message);
        assert!(
            e.column >= 1 && e.column <= bad.chars().count() + 1,
            "{bad}: {e:?}"
        );
        parse(fixed).unwrap_or_else(|e| panic!("{bad}, fixed as the hint says, {fixed}: {e:?}"));
    }
}

/// A `cases` environment reads as one relation per case, its condition kept apart.
#[test]
fn cases_read_as_one_relation_per_case() {
    let same = |a: &str, b: &str| {
        let (x, y) = (parse(a).unwrap(), parse(b).unwrap());
        assert_eq!(x.0, y.0, "{a} vs {b}");
        let names = |o: &[super::Occurrence]| {
            let mut v: Vec<String> = o.iter().map(|(s, _)| s.to_string()).collect();
            v.sort();
            v
        };
        assert_eq!(names(&x.1), names(&y.1), "{a} vs {b}: the symbols read");
    };
    same(
        r"f = \begin{cases} 1 & b > 0 \\ 2 & b < 0 \end{cases}",
        r"f = 1 \quad \text{for } b > 0, \qquad f = 2 \quad \text{for } b < 0",
    );
    same(
        r"f &= \begin{cases} \frac{1}{2}, & \text{if } b > 0, \\ 2 k, & \text{otherwise}. \end{cases}",
        r"f = \frac{1}{2} \quad \text{if } b > 0, \qquad f = 2 k",
    );
    same(
        r"x = a \\ f = \begin{cases} 1 & b \ge 0 \end{cases} \label{e9}",
        r"x = a, \qquad f = 1 \quad \text{for } b \ge 0",
    );
    // A message about a case points into the case as written.
    let bad = r"f = \begin{cases} 1 & b > 0 \\ 2 + & b < 0 \end{cases}";
    let e = parse(bad).unwrap_err();
    assert!(e.column > bad.find(r"2 +").unwrap(), "{e:?}");
}

/// The forms of the issue, each beside the form the paper's transcription uses.
#[test]
fn the_authors_forms_read_as_the_transcription() {
    let same =
        |a: &str, b: &str| assert_eq!(parse(a).unwrap().0, parse(b).unwrap().0, "{a} vs {b}");
    same(r"x = \frac12 + \frac ba", r"x = \frac{1}{2} + \frac{b}{a}");
    same(r"x = {a \over b}", r"x = \frac{a}{b}");
    same(
        r"\dot\alpha = \mathbf a \cdot \mathbf a",
        r"\dot{\alpha} = \mathbf{a} \cdot \mathbf{a}",
    );
    same(
        r"{{\rm d} \Omega \over {\rm d}t} = 0",
        r"\frac{d \Omega}{dt} = 0",
    );
    same(
        r"\frac{\mathrm{d}}{\mathrm{d}t}\Omega = 0",
        r"\frac{d \Omega}{dt} = 0",
    );
    same(r"d\Omega/dt = 0", r"\frac{d \Omega}{dt} = 0");
    same(r"d^2\Omega/dt^2 = 0", r"\frac{d^2 \Omega}{dt^2} = 0");
    same(r"x = |b|", r"x = \left| b \right|");
    same(r"x &= a \\ &= b", r"x = a = b");
    same(r"x &=& a \nonumber \\ && + b \label{e1}", r"x = a + b");
    same(
        r"\begin{aligned} x &= a \\ &= b \end{aligned}",
        r"x = a = b",
    );
    same(r"\begin{split} x &= a \end{split} \tag{3}", r"x = a");
    same(
        r"x = \sin{\alpha} + \operatorname{sin}\alpha + \mathrm{sin}\alpha",
        r"x = \sin\alpha + \sin\alpha + \sin\alpha",
    );
    same(r"x = a \quad \text{for } b = 0", r"x = a");
    same(r"x = a \quad \text{(the steady motion)}", r"x = a");
    same("ω = α − β", r"\omega = \alpha - \beta");
    same(
        r"x = \vec{\vec I} \cdot \vec\omega",
        r"x = \mathbf{I} \cdot \vec{\omega}",
    );
}
