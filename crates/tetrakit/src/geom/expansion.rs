//! Exact floating-point expansions (Shewchuk, "Adaptive precision floating-point
//! arithmetic and fast robust geometric predicates", 1997): a number is kept as a sum of
//! non-overlapping `f64` components, and sums, differences and products are exact.
//!
//! The `robust` crate gives the *signs* of its four predicates; a few tests need the sign
//! of a polynomial that is not one of them (the sum of many determinants for a surface's
//! enclosed volume, or a plane spanned by an edge and a direction). Those are computed here,
//! behind a floating-point filter at the call site. Products use fused multiply-add for the
//! exact rounding error, which is exact as long as nothing underflows; input coordinates are
//! confined to `[2^-142, 2^201]` (see [`coordinate_in_range`](super::coordinate_in_range)),
//! so products of up to six of them stay well inside the normal range.

use super::Point3;

/// An exact sum of non-overlapping `f64` components in increasing magnitude.
///
/// ```
/// use tetrakit::geom::Expansion;
/// let big = Expansion::from(1e300);
/// let tiny = Expansion::from(1e-300);
/// let s = big.add(&tiny).sub(&big);
/// assert_eq!(s.sign(), 1); // exact: plain f64 would give 0
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Expansion(Vec<f64>);

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl From<f64> for Expansion {
    fn from(x: f64) -> Self {
        if x == 0.0 {
            Expansion(Vec::new())
        } else {
            Expansion(vec![x])
        }
    }
}

impl Expansion {
    /// The exact difference `a - b`.
    pub fn diff(a: f64, b: f64) -> Self {
        let (s, e) = two_sum(a, -b);
        Expansion([e, s].into_iter().filter(|&x| x != 0.0).collect())
    }

    /// The exact sum (Shewchuk's EXPANSION-SUM with zero elimination).
    pub fn add(&self, other: &Expansion) -> Expansion {
        let mut out = self.0.clone();
        for &b in &other.0 {
            let mut q = b;
            let mut next = Vec::with_capacity(out.len() + 1);
            for &h in &out {
                let (s, e) = two_sum(q, h);
                q = s;
                if e != 0.0 {
                    next.push(e);
                }
            }
            if q != 0.0 {
                next.push(q);
            }
            out = next;
        }
        Expansion(out)
    }

    /// The exact negation.
    pub fn neg(&self) -> Expansion {
        Expansion(self.0.iter().map(|x| -x).collect())
    }

    /// The exact difference.
    pub fn sub(&self, other: &Expansion) -> Expansion {
        self.add(&other.neg())
    }

    /// The exact product by one `f64` (SCALE-EXPANSION).
    pub fn scale(&self, b: f64) -> Expansion {
        let mut out = Expansion::default();
        for &a in &self.0 {
            let (p, e) = two_product(a, b);
            out = out.add(&Expansion(
                [e, p].into_iter().filter(|&x| x != 0.0).collect(),
            ));
        }
        out
    }

    /// The exact product.
    pub fn mul(&self, other: &Expansion) -> Expansion {
        other
            .0
            .iter()
            .fold(Expansion::default(), |acc, &b| acc.add(&self.scale(b)))
    }

    /// The sign: -1, 0 or 1 (the sign of the largest component).
    pub fn sign(&self) -> i8 {
        match self.0.last() {
            Some(&x) if x > 0.0 => 1,
            Some(_) => -1,
            None => 0,
        }
    }

    /// The non-overlapping components, in increasing magnitude.
    pub fn components(&self) -> &[f64] {
        &self.0
    }

    /// The nearest `f64` to the sum, up to the rounding of the final additions.
    pub fn estimate(&self) -> f64 {
        self.0.iter().sum()
    }
}

/// The exact determinant `det[u, v, w]` of three vectors given as expansions.
pub fn det3(u: &[Expansion; 3], v: &[Expansion; 3], w: &[Expansion; 3]) -> Expansion {
    let minor = |i: usize, j: usize| v[i].mul(&w[j]).sub(&v[j].mul(&w[i]));
    u[0].mul(&minor(1, 2))
        .sub(&u[1].mul(&minor(0, 2)))
        .add(&u[2].mul(&minor(0, 1)))
}

/// The exact vector `b - a`.
pub fn vector(a: &Point3, b: &Point3) -> [Expansion; 3] {
    [0, 1, 2].map(|i| Expansion::diff(b[i], a[i]))
}

/// The exact value of `det[b - a, c - a, d - a]` (six times the signed volume of `abcd`,
/// positive when the tetrahedron is positively oriented).
pub fn orient3d_value(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> Expansion {
    det3(&vector(a, b), &vector(a, c), &vector(a, d))
}

/// The sign of `det[a2 - a1, b2 - b1, x - a1]`: the side of `x` relative to the plane
/// through `a1` spanned by the directions of the segments `a1a2` and `b1b2` (0 when the
/// directions are parallel, since the plane is then undefined and the determinant vanishes).
pub fn edge_edge_side(a1: &Point3, a2: &Point3, b1: &Point3, b2: &Point3, x: &Point3) -> i8 {
    det3(&vector(a1, a2), &vector(b1, b2), &vector(a1, x)).sign()
}

/// True when the directions of `a1a2` and `b1b2` are parallel (their cross product is
/// exactly zero).
pub fn parallel(a1: &Point3, a2: &Point3, b1: &Point3, b2: &Point3) -> bool {
    let (u, v) = (vector(a1, a2), vector(b1, b2));
    let cross = |i: usize, j: usize| u[i].mul(&v[j]).sub(&u[j].mul(&v[i]));
    cross(1, 2).sign() == 0 && cross(2, 0).sign() == 0 && cross(0, 1).sign() == 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::orient3d;
    use crate::rng::Rng;

    #[test]
    fn orient3d_value_has_the_sign_of_orient3d() {
        let mut rng = Rng::new(7);
        for round in 0..2000 {
            let mut p = || {
                let g = |r: &mut Rng| {
                    if round % 2 == 0 {
                        r.below(5) as f64
                    } else {
                        r.unit() * 1e3 - 5e2
                    }
                };
                [g(&mut rng), g(&mut rng), g(&mut rng)]
            };
            let (a, b, c, d) = (p(), p(), p(), p());
            assert_eq!(
                orient3d_value(&a, &b, &c, &d).sign(),
                orient3d(&a, &b, &c, &d)
            );
        }
    }

    #[test]
    fn integer_products_are_exact() {
        let mut rng = Rng::new(3);
        for _ in 0..1000 {
            let x = rng.below(1 << 40) as i64 - (1 << 39);
            let y = rng.below(1 << 40) as i64 - (1 << 39);
            let z = rng.below(1 << 20) as i64;
            let e = Expansion::from(x as f64)
                .mul(&Expansion::from(y as f64))
                .add(&Expansion::from(z as f64));
            let exact = x as i128 * y as i128 + z as i128;
            assert_eq!(e.sign() as i128, exact.signum());
            let back: i128 = e.0.iter().map(|&c| c as i128).sum();
            assert_eq!(back, exact);
        }
    }

    #[test]
    fn edge_edge_side_matches_integer_arithmetic() {
        let mut rng = Rng::new(11);
        for _ in 0..2000 {
            let mut p = || [0, 1, 2].map(|_| rng.below(7) as f64 - 3.0);
            let (a1, a2, b1, b2, x) = (p(), p(), p(), p(), p());
            let v = |a: &Point3, b: &Point3| [0, 1, 2].map(|i| (b[i] - a[i]) as i64);
            let (u, w, y) = (v(&a1, &a2), v(&b1, &b2), v(&a1, &x));
            let det = u[0] * (w[1] * y[2] - w[2] * y[1]) - u[1] * (w[0] * y[2] - w[2] * y[0])
                + u[2] * (w[0] * y[1] - w[1] * y[0]);
            assert_eq!(edge_edge_side(&a1, &a2, &b1, &b2, &x) as i64, det.signum());
        }
    }
}
