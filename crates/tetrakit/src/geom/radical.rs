//! Certified weights: intervals of sums of lengths, and the exact comparison of two sums
//! of square roots.
//!
//! Lengths are square roots of squared lengths, which are exact dyadic rationals
//! ([`Expansion`]s). Most comparisons of triangulation weights are decided by
//! [`Interval`]s with outward rounding. When two intervals overlap, [`compare_root_sums`]
//! decides exactly:
//!
//! 1. every term `√(N·2^e)` becomes `2^⌊e/2⌋·√R` with an integer radicand `R` (`N` or
//!    `2N`); equal radicands are merged;
//! 2. two radicands whose product is a perfect square are *equivalent* (`√R_j` is a
//!    rational multiple of `√R_i`) and are merged with a rational factor;
//! 3. square roots of pairwise inequivalent positive integers are linearly independent
//!    over ℚ (Besicovitch, 1940), so the difference is zero exactly when every merged
//!    coefficient is zero (this is how ties on grids and regular polygons are certified);
//! 4. otherwise the difference is non-zero, and it is bracketed with integer square roots
//!    at 64, 128, 256, … bits until the bracket excludes zero, which must happen.

use super::Expansion;
use num_bigint::{BigInt, BigUint, Sign};
use std::cmp::Ordering;

/// A closed interval `[lo, hi]` of reals with `f64` ends, for certified weights.
///
/// ```
/// use tetrakit::geom::Interval;
/// let w = Interval::length(&[0.0, 0.0], &[3.0, 4.0]).plus(Interval::length(&[0.0, 0.0], &[1.0, 0.0]));
/// assert!(w.lo <= 6.0 && 6.0 <= w.hi && w.hi - w.lo < 1e-13);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// Relative error bound of a length computed in `f64` (`3ε` plus margin; module docs).
const LENGTH_ERROR: f64 = 8.881784197001252e-16; // 2^-50

impl Interval {
    /// The interval `[0, 0]`.
    pub const ZERO: Interval = Interval { lo: 0.0, hi: 0.0 };

    /// An interval containing the Euclidean length `|ab|`. The length computed in `f64`
    /// has relative error below `3ε` (two rounded differences, squares and sum, square
    /// root), so widening by `2^-50` relative and one ulp is safe.
    pub fn length(a: &[f64; 2], b: &[f64; 2]) -> Interval {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let l = (dx * dx + dy * dy).sqrt();
        Interval {
            lo: (l * (1.0 - LENGTH_ERROR)).next_down().max(0.0),
            hi: (l * (1.0 + LENGTH_ERROR)).next_up(),
        }
    }

    /// The interval sum, rounded outward.
    pub fn plus(self, other: Interval) -> Interval {
        Interval {
            lo: (self.lo + other.lo).next_down(),
            hi: (self.hi + other.hi).next_up(),
        }
    }

    /// The midpoint, a best estimate.
    pub fn mid(self) -> f64 {
        0.5 * (self.lo + self.hi)
    }

    /// `Some(ordering)` when the intervals decide it (disjoint), `None` when they overlap.
    pub fn certain_cmp(self, other: Interval) -> Option<Ordering> {
        if self.hi < other.lo {
            Some(Ordering::Less)
        } else if self.lo > other.hi {
            Some(Ordering::Greater)
        } else {
            None
        }
    }
}

/// `x = m·2^e` with an integer `m` (exact for every finite `f64`).
fn decompose(x: f64) -> (i64, i32) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp - 1075)
    };
    (if x < 0.0 { -m } else { m }, e)
}

/// A non-negative dyadic rational `value = n·2^e` as an integer `n` and exponent `e`.
fn to_dyadic(x: &Expansion) -> (BigUint, i32) {
    let parts: Vec<(i64, i32)> = x.components().iter().map(|&c| decompose(c)).collect();
    let Some(e0) = parts.iter().map(|p| p.1).min() else {
        return (BigUint::default(), 0);
    };
    let n: BigInt = parts
        .iter()
        .map(|&(m, e)| BigInt::from(m) << ((e - e0) as usize))
        .sum();
    (
        n.to_biguint().expect("squared lengths are non-negative"),
        e0,
    )
}

/// A term `coef·√radicand` with a rational coefficient `num/den`.
#[derive(Clone, Debug)]
struct Term {
    num: BigInt,
    den: BigUint,
    radicand: BigUint,
}

fn term(x: &Expansion, sign: Sign) -> Option<Term> {
    let (n, e) = to_dyadic(x);
    if n == BigUint::default() {
        return None;
    }
    // √(n·2^e) = 2^⌊e/2⌋ √(n·2^(e mod 2)).
    let half = e.div_euclid(2);
    let radicand = if e.rem_euclid(2) == 1 { n << 1usize } else { n };
    let (num, den) = if half >= 0 {
        (BigUint::from(1u8) << (half as usize), BigUint::from(1u8))
    } else {
        (BigUint::from(1u8), BigUint::from(1u8) << ((-half) as usize))
    };
    Some(Term {
        num: BigInt::from_biguint(sign, num),
        den,
        radicand,
    })
}

fn add_to(t: &mut Term, num: BigInt, den: &BigUint) {
    // t.num/t.den + num/den
    t.num = &t.num * BigInt::from(den.clone()) + num * BigInt::from(t.den.clone());
    t.den = &t.den * den;
}

/// The exact sign of `Σ √a_i − Σ √b_j` for non-negative exact values (squared lengths).
pub fn compare_root_sums(a: &[Expansion], b: &[Expansion]) -> Ordering {
    let (a, b) = cancel_equal(a, b);
    if a.is_empty() && b.is_empty() {
        return Ordering::Equal;
    }
    double_double_cmp(&a, &b).unwrap_or_else(|| exact_cmp(&a, &b))
}

/// The exact comparison by integer arithmetic (steps 1–4 of the module docs).
fn exact_cmp(a: &[Expansion], b: &[Expansion]) -> Ordering {
    let mut terms: Vec<Term> = Vec::new();
    let items = a.iter().map(|x| (x, Sign::Plus));
    for (x, sign) in items.chain(b.iter().map(|x| (x, Sign::Minus))) {
        let Some(t) = term(x, sign) else { continue };
        match terms.iter_mut().find(|u| u.radicand == t.radicand) {
            Some(u) => add_to(u, t.num, &t.den),
            None => terms.push(t),
        }
    }
    merge_equivalent(&mut terms);
    terms.retain(|t| t.num.sign() != Sign::NoSign);
    if terms.is_empty() {
        return Ordering::Equal;
    }
    bracket_sign(&terms)
}

/// The two lists without the values they share (mirror images, repeated lengths).
fn cancel_equal(a: &[Expansion], b: &[Expansion]) -> (Vec<Expansion>, Vec<Expansion>) {
    let exact = |x: &Expansion, y: &Expansion| x.sub(y).sign().cmp(&0);
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    a.sort_by(exact);
    b.sort_by(exact);
    let (mut ra, mut rb) = (Vec::new(), Vec::new());
    let (mut i, mut j) = (0, 0);
    while i < a.len() || j < b.len() {
        let o = match (a.get(i), b.get(j)) {
            (Some(x), Some(y)) => exact(x, y),
            (Some(_), None) => Ordering::Less,
            _ => Ordering::Greater,
        };
        match o {
            Ordering::Less => {
                ra.push(a[i].clone());
                i += 1;
            }
            Ordering::Greater => {
                rb.push(b[j].clone());
                j += 1;
            }
            Ordering::Equal => {
                i += 1;
                j += 1;
            }
        }
    }
    (ra, rb)
}

/// `(s, e)` with `s + e = a + b` exactly (Knuth's TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    (s, (a - (s - bv)) + (b - bv))
}

/// `(s, e)` with `s + e = a + b` exactly, for `|a| ≥ |b|`.
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// A double-double number `hi + lo` (`|lo| ≤ ulp(hi)/2`), for sums of lengths whose
/// error is a few `u² = 2^-106` per operation: the filter between [`Interval`]s and the
/// exact [`compare_root_sums`].
///
/// Error model, used by [`DoubleDouble::certain_cmp`]: a length is within `2^-100`
/// relative of `|ab|` (the squared length to `2^-103`, one Newton step for the root),
/// and an addition of non-negative numbers within `3u² + 13u³` relative (Joldes, Muller
/// and Popescu's AccurateDWPlusDW), so a sum of `k` lengths is within
/// `(1 + k/8)·2^-100` of exact; the tests use `(2k + 2)·2^-96`, far above that.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DoubleDouble {
    /// The leading part.
    pub hi: f64,
    /// The trailing part.
    pub lo: f64,
}

impl DoubleDouble {
    /// Zero.
    pub const ZERO: DoubleDouble = DoubleDouble { hi: 0.0, lo: 0.0 };

    /// `|ab|` within `2^-100` relative.
    pub fn length(a: &[f64; 2], b: &[f64; 2]) -> DoubleDouble {
        let (dx, ex) = two_sum(b[0], -a[0]);
        let (dy, ey) = two_sum(b[1], -a[1]);
        let (px, qx) = (dx * dx, dx.mul_add(dx, -(dx * dx)));
        let (py, qy) = (dy * dy, dy.mul_add(dy, -(dy * dy)));
        // dx² + dy² = px + qx + py + qy + 2(dx·ex + dy·ey) + ex² + ey²; the last two are
        // below 2^-104 relative and dropped.
        let tail = qx + qy + 2.0 * (dx * ex + dy * ey);
        let square = DoubleDouble { hi: px, lo: 0.0 }
            .plus(DoubleDouble { hi: py, lo: 0.0 })
            .plus(DoubleDouble { hi: tail, lo: 0.0 });
        square.sqrt()
    }

    fn sqrt(self) -> DoubleDouble {
        if self.hi <= 0.0 {
            return DoubleDouble::ZERO;
        }
        let r = self.hi.sqrt();
        let residual = (-r).mul_add(r, self.hi) + self.lo;
        let (hi, lo) = fast_two_sum(r, residual / (2.0 * r));
        DoubleDouble { hi, lo }
    }

    /// The sum.
    pub fn plus(self, y: DoubleDouble) -> DoubleDouble {
        let (s, e) = two_sum(self.hi, y.hi);
        let (t, f) = two_sum(self.lo, y.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        DoubleDouble { hi, lo }
    }

    fn neg(self) -> DoubleDouble {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// An upper bound on the error of a sum of at most `k` lengths close to `self`.
    fn error(self, k: usize) -> f64 {
        self.hi.abs() * (1.0 + 1e-10) * (2 * k + 2) as f64 * 2f64.powi(-96)
    }

    /// `Some` when the two sums, of at most `k` lengths each, are certainly ordered.
    pub fn certain_cmp(self, other: DoubleDouble, k: usize) -> Option<Ordering> {
        let d = self.plus(other.neg());
        let bound = 2.0 * (self.error(k) + other.error(k));
        if d.hi.abs() > bound {
            d.hi.partial_cmp(&0.0)
        } else {
            None
        }
    }

    /// A certified interval for a sum of at most `k` lengths.
    pub fn interval(self, k: usize) -> Interval {
        let e = self.error(k);
        Interval {
            lo: (self.hi + self.lo - e).next_down().max(0.0),
            hi: (self.hi + self.lo + e).next_up(),
        }
    }
}

/// `√x` of an exact non-negative value, within `2^-100` relative.
fn dd_sqrt(x: &Expansion) -> DoubleDouble {
    x.components()
        .iter()
        .fold(DoubleDouble::ZERO, |acc, &c| {
            acc.plus(DoubleDouble { hi: c, lo: 0.0 })
        })
        .sqrt()
}

/// The sign of `Σ √a_i − Σ √b_j` in double-double when it clears the error bound.
fn double_double_cmp(a: &[Expansion], b: &[Expansion]) -> Option<Ordering> {
    let sum = |v: &[Expansion]| {
        v.iter()
            .fold(DoubleDouble::ZERO, |acc, x| acc.plus(dd_sqrt(x)))
    };
    sum(a).certain_cmp(sum(b), a.len().max(b.len()))
}

/// Merges terms whose radicands differ by a rational square: `√R_j = (s/R_i)·√R_i`
/// when `R_i·R_j = s²`.
fn merge_equivalent(terms: &mut Vec<Term>) {
    let mut i = 0;
    while i < terms.len() {
        let mut j = i + 1;
        while j < terms.len() {
            let prod = &terms[i].radicand * &terms[j].radicand;
            let s = prod.sqrt();
            if &s * &s == prod {
                let t = terms.swap_remove(j);
                // (t.num/t.den)·(s/R_i)·√R_i
                let den = t.den * &terms[i].radicand;
                add_to(&mut terms[i], t.num * BigInt::from(s), &den);
            } else {
                j += 1;
            }
        }
        i += 1;
    }
}

/// The sign of a non-zero `Σ c_i √R_i`, by integer square roots of increasing precision.
fn bracket_sign(terms: &[Term]) -> Ordering {
    // Scale to integer coefficients m_i = c_i · Π den.
    let common: BigUint = terms.iter().fold(BigUint::from(1u8), |acc, t| acc * &t.den);
    let coefs: Vec<BigInt> = terms
        .iter()
        .map(|t| &t.num * BigInt::from(&common / &t.den))
        .collect();
    let mut bits = 64usize;
    loop {
        let (mut lo, mut hi) = (BigInt::default(), BigInt::default());
        for (t, m) in terms.iter().zip(&coefs) {
            let s = BigInt::from((&t.radicand << (2 * bits)).sqrt());
            let s1 = &s + 1;
            if m.sign() == Sign::Plus {
                lo += m * &s;
                hi += m * &s1;
            } else {
                lo += m * &s1;
                hi += m * &s;
            }
        }
        if lo.sign() == Sign::Plus {
            return Ordering::Greater;
        }
        if hi.sign() == Sign::Minus {
            return Ordering::Less;
        }
        bits *= 2;
    }
}

#[cfg(test)]
mod tests {
    /// `DoubleDouble` on a worked example.
    #[test]
    fn double_double_example() {
        use crate::geom::DoubleDouble;
        use std::cmp::Ordering;
        let (o, u, v) = ([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]);
        let w = [2.0, 2.0f64.next_up()]; // |ow| exceeds 2√2 by about 1e-16 relative
        let two = DoubleDouble::length(&o, &u).plus(DoubleDouble::length(&o, &u));
        assert_eq!(
            two.certain_cmp(DoubleDouble::length(&o, &w), 2),
            Some(Ordering::Less)
        );
        // An exact tie (√2 + √2 = √8) is never decided here.
        assert_eq!(two.certain_cmp(DoubleDouble::length(&o, &v), 2), None);
    }

    /// `compare_root_sums` on a worked example.
    #[test]
    fn compare_root_sums_example() {
        use crate::geom::{Expansion, compare_root_sums};
        use std::cmp::Ordering;
        let e = |x: f64| Expansion::from(x);
        // √8 = 2√2 exactly, and √2 + √8 = √18.
        assert_eq!(
            compare_root_sums(&[e(2.0), e(8.0)], &[e(18.0)]),
            Ordering::Equal
        );
        assert_eq!(
            compare_root_sums(&[e(2.0), e(3.0)], &[e(10.0)]),
            Ordering::Less
        );
    }

    use super::*;
    use crate::geom::squared_length;

    #[test]
    fn decompose_is_exact() {
        for x in [1.0, -3.5, 0.1, 1e-300, 5e-324, 1e300] {
            let (m, e) = decompose(x);
            assert_eq!(m as f64 * 2f64.powi(e), x);
        }
    }

    /// The double-double filter never contradicts the exact comparison: sums of up to
    /// five lengths against the same sums with one endpoint moved by a few ulps
    /// (differences near 1e-16 relative, below what `f64` intervals resolve).
    #[test]
    fn double_double_filter_agrees_with_exact_comparison() {
        let mut rng = crate::rng::Rng::new(77);
        let mut decided = 0;
        for _ in 0..2000 {
            let k = 1 + rng.below(5);
            let pts: Vec<[f64; 2]> = (0..2 * k)
                .map(|_| [rng.unit() * 100.0, rng.unit() * 100.0])
                .collect();
            let sq = |v: &[[f64; 2]]| -> Vec<Expansion> {
                v.chunks(2).map(|c| squared_length(&c[0], &c[1])).collect()
            };
            let mut moved = pts.clone();
            let t = rng.below(2 * k);
            let axis = rng.below(2);
            for _ in 0..1 + rng.below(3) {
                moved[t][axis] = moved[t][axis].next_up();
            }
            let (a, b) = (sq(&pts), sq(&moved));
            let exact = exact_cmp(&a, &b);
            if let Some(o) = double_double_cmp(&a, &b) {
                assert_eq!(o, exact);
                decided += 1;
            }
            assert_eq!(compare_root_sums(&a, &b), exact);
        }
        assert!(decided > 1000, "{decided}");
    }

    #[test]
    fn ties_on_grids_are_exact() {
        // Two triangulations of a unit square: diagonals of equal length.
        let d1 = squared_length(&[0.0, 0.0], &[1.0, 1.0]);
        let d2 = squared_length(&[1.0, 0.0], &[0.0, 1.0]);
        assert_eq!(compare_root_sums(&[d1], &[d2]), Ordering::Equal);
        // 0.75√2 versus 0.25√2 + 0.5√2 along a diagonal with dyadic coordinates: the
        // radicands 1.125, 0.125 and 0.5 differ by rational squares, so the sums are
        // exactly equal, and a tiny shift of one point must break the tie.
        let e = |a: [f64; 2], b: [f64; 2]| squared_length(&a, &b);
        let lhs = [e([0.0, 0.0], [0.75, 0.75])];
        let rhs = [e([0.0, 0.0], [0.25, 0.25]), e([0.25, 0.25], [0.75, 0.75])];
        assert_eq!(compare_root_sums(&lhs, &rhs), Ordering::Equal);
        let moved = [
            e([0.0, 0.0], [0.25, 0.25 + 2f64.powi(-40)]),
            e([0.25, 0.25 + 2f64.powi(-40)], [0.75, 0.75]),
        ];
        assert_eq!(compare_root_sums(&lhs, &moved), Ordering::Less);
    }

    #[test]
    fn near_ties_are_separated() {
        // √(10^6 + 1) + √(10^6 - 1) < 2·10^3, by about 2.5e-10.
        let e = |x: f64| Expansion::from(x);
        assert_eq!(
            compare_root_sums(&[e(1e6 + 1.0), e(1e6 - 1.0)], &[e(1e6), e(1e6)]),
            Ordering::Less
        );
    }
}
