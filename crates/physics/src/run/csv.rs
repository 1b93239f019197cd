//! One recorded row as a line of CSV.

/// Appends one CSV row to `out`: each number as the shortest decimal that reads back to the
/// same double (`zmij`, Zverovich's algorithm; `NaN`, `inf` and `-inf` as Rust writes them),
/// separated by commas, ended by a newline. A number takes at most 24 bytes
/// (`-1.2345678901234567e-308`).
pub fn csv_row(row: &[f64], out: &mut Vec<u8>) {
    let mut buffer = zmij::Buffer::new();
    for (i, &v) in row.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        out.extend_from_slice(buffer.format(v).as_bytes());
    }
    out.push(b'\n');
}

#[cfg(test)]
mod tests {
    use super::csv_row;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn line(row: &[f64]) -> String {
        let mut out = Vec::new();
        csv_row(row, &mut out);
        String::from_utf8(out).expect("ASCII")
    }

    #[test]
    fn a_row_is_its_numbers_shortest_between_commas() {
        assert_eq!(
            line(&[0.0, 0.5, -1e-300, 3.0, 0.1, f64::NAN, f64::INFINITY]),
            "0.0,0.5,-1e-300,3.0,0.1,NaN,inf\n"
        );
        assert_eq!(line(&[]), "\n");
    }

    #[test]
    fn every_number_reads_back_to_the_same_double_in_at_most_24_bytes() {
        let mut rng = ChaCha8Rng::seed_from_u64(49);
        let special = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE / 3.0,
            5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            1.0 - f64::EPSILON / 2.0,
            -1.2345678901234567e-308,
            1.2345678901234567e-5,
            1234567890123456.7,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        // Every bit pattern is a double: random ones cover all exponents, subnormals and both
        // signs; random values of a run's sizes cover its usual digits.
        let random = (0..200_000).map(|i| {
            if i % 2 == 0 {
                f64::from_bits(rng.random::<u64>())
            } else {
                rng.random_range(-1.0..1.0) * 10f64.powi(rng.random_range(-20..20))
            }
        });
        let mut checked = 0;
        for v in special.into_iter().chain(random).filter(|v| !v.is_nan()) {
            let text = line(&[v]);
            let number = text.strip_suffix('\n').expect("a newline");
            assert!(number.len() <= 24, "{number} is longer than 24 bytes");
            let back: f64 = number.parse().expect("a number");
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e} was written {number}");
            checked += 1;
        }
        assert!(checked > 200_000 - 1_000, "only {checked} numbers checked");
        assert!(line(&[f64::NAN])
            .trim_end()
            .parse::<f64>()
            .expect("NaN")
            .is_nan());
    }
}
