//! Exact orientation predicates (Shewchuk's adaptive arithmetic via the `robust` crate).
//!
//! Every geometric decision in tetrakit goes through this module. Inputs are `f64`
//! coordinates taken as the exact dyadic rationals they are; the answers are exact
//! provided every coordinate passes [`coordinate_in_range`].
//!
//! Sign conventions (ARCHITECTURE.md, "Conventions"): [`orient3d`] is positive when
//! `det[b−a, c−a, d−a] > 0` (TetGen/VTK's positive tetrahedron), which is the *opposite* sign of
//! `robust::orient3d`. [`orient2d`] is positive when `a, b, c` turn counter-clockwise.

use robust::{Coord, Coord3D};

/// A point in 3D.
pub type Point3 = [f64; 3];
/// A point in 2D.
pub type Point2 = [f64; 2];

/// Smallest positive magnitude for which the predicates stay exact (about 2^-142).
pub const MIN_MAGNITUDE: f64 = 1.793662034335766e-43; // 2^-142
/// Largest magnitude for which the predicates stay exact (about 2^201).
pub const MAX_MAGNITUDE: f64 = 3.2138760885179806e60; // 2^201

/// True when `x` is finite and either zero or of magnitude in
/// [[`MIN_MAGNITUDE`], [`MAX_MAGNITUDE`]], the range where Shewchuk's predicates are exact.
///
/// ```
/// use tetrakit::geom::coordinate_in_range;
/// assert!(coordinate_in_range(0.0) && coordinate_in_range(-1.5));
/// assert!(!coordinate_in_range(f64::NAN) && !coordinate_in_range(1e300));
/// ```
pub fn coordinate_in_range(x: f64) -> bool {
    x == 0.0 || (x.is_finite() && (MIN_MAGNITUDE..=MAX_MAGNITUDE).contains(&x.abs()))
}

#[inline]
fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

#[inline]
fn c3(p: &Point3) -> Coord3D<f64> {
    Coord3D {
        x: p[0],
        y: p[1],
        z: p[2],
    }
}

/// Sign of `det[b−a, c−a, d−a]`: +1 when `abcd` is a positively oriented tetrahedron.
///
/// ```
/// use tetrakit::geom::orient3d;
/// let o = [0.0, 0.0, 0.0];
/// assert_eq!(orient3d(&o, &[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0], &[0.0, 0.0, 1.0]), 1);
/// assert_eq!(orient3d(&o, &[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0], &[5.0, 7.0, 0.0]), 0);
/// ```
///
/// The floating-point filter is Shewchuk's (error bound (7 + 56u)u of the permanent);
/// when it cannot decide and two of the points coincide, or all four share a coordinate,
/// the answer is an exact 0 without the adaptive stages, which otherwise dominate tests
/// between faces sharing vertices and on a box's facets.
#[inline]
pub fn orient3d(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> i8 {
    let (ad, bd, cd) = (
        [a[0] - d[0], a[1] - d[1], a[2] - d[2]],
        [b[0] - d[0], b[1] - d[1], b[2] - d[2]],
        [c[0] - d[0], c[1] - d[1], c[2] - d[2]],
    );
    let (det, permanent) = shewchuk_det(&ad, &bd, &cd);
    let u = f64::EPSILON / 2.0;
    let bound = (7.0 + 56.0 * u) * u * permanent;
    // robust::orient3d(a, b, c, d) is this det; ours is its negation.
    if det > bound {
        return -1;
    }
    if -det > bound {
        return 1;
    }
    unfiltered(a, b, c, d, [ad, bd, cd], det)
}

/// [`orient3d`] where a float filter has not decided (its own, or a [`PlaneFilter`]'s):
/// the exact answer without the filter again.
#[inline]
pub(crate) fn orient3d_unfiltered(a: &Point3, b: &Point3, c: &Point3, d: &Point3) -> i8 {
    let (ad, bd, cd) = (
        [a[0] - d[0], a[1] - d[1], a[2] - d[2]],
        [b[0] - d[0], b[1] - d[1], b[2] - d[2]],
        [c[0] - d[0], c[1] - d[1], c[2] - d[2]],
    );
    let (det, _) = shewchuk_det(&ad, &bd, &cd);
    unfiltered(a, b, c, d, [ad, bd, cd], det)
}

/// The exact stages of [`orient3d`], given the differences `[a − d, b − d, c − d]` and
/// their float determinant `det`.
fn unfiltered(
    a: &Point3,
    b: &Point3,
    c: &Point3,
    d: &Point3,
    [ad, bd, cd]: [Point3; 3],
    det: f64,
) -> i8 {
    if a == b || a == c || a == d || b == c || b == d || c == d {
        return 0;
    }
    // Four points in one axis-parallel plane (a box's facet, a lattice circle): an exact
    // 0, since two floats subtract to exactly 0 only when they are equal.
    if (0..3).any(|k| ad[k] == 0.0 && bd[k] == 0.0 && cd[k] == 0.0) {
        return 0;
    }
    // Small integers (up to a common power of two), as on lattices and grids: `det`
    // had no rounding at all (see [`computed_exactly`]), so its sign is the answer.
    let f = Frame::new(d);
    if computed_exactly(&f.dir(a), &f.dir(b), &f.dir(c)) {
        return -sign(det);
    }
    -sign(robust::orient3d(c3(a), c3(b), c3(c), c3(d)))
}

/// `det[ad, bd, cd]` in floats, expanded along the last column as in Shewchuk's
/// `orient3dfast`, and its permanent (for his error bound).
#[inline]
fn shewchuk_det(ad: &Point3, bd: &Point3, cd: &Point3) -> (f64, f64) {
    let (bc, cb) = (bd[0] * cd[1], cd[0] * bd[1]);
    let (ca, ac) = (cd[0] * ad[1], ad[0] * cd[1]);
    let (ab, ba) = (ad[0] * bd[1], bd[0] * ad[1]);
    let det = ad[2] * (bc - cb) + bd[2] * (ca - ac) + cd[2] * (ab - ba);
    let permanent = (bc.abs() + cb.abs()) * ad[2].abs()
        + (ca.abs() + ac.abs()) * bd[2].abs()
        + (ab.abs() + ba.abs()) * cd[2].abs();
    (det, permanent)
}

/// True when a 3×3 determinant of these directions, evaluated as a sum of products of
/// differences of products, is computed without any rounding: the differences were
/// exact and their nine components span at most 15 bits, so each is `m·2^e` with
/// `|m| < 2^16` for one `e`; a product of two is below `2^32·2^2e`, their difference
/// below `2^33·2^2e`, a product of three below `2^49·2^3e` and the sum of three below
/// `2^51·2^3e`, all multiples of the unit they are counted in: exact in 53 bits.
#[inline]
fn computed_exactly(da: &Dir, db: &Dir, dc: &Dir) -> bool {
    let inexact = da.hi == i32::MIN || db.hi == i32::MIN || dc.hi == i32::MIN;
    let lo = da.lo.min(db.lo).min(dc.lo);
    let hi = da.hi.max(db.hi).max(dc.hi);
    !inexact && (lo == i32::MAX || hi - lo <= 15)
}

/// Bound on the rounding error of the fast determinant in [`Frame`], relative to its
/// permanent. Shewchuk's own bound for the same evaluation is (7 + 56u)u; we use 16u.
const FRAME_ERR: f64 = 16.0 * f64::EPSILON / 2.0;

/// A direction `p − v` prepared for [`Frame::sign`]: its rounded value and, when the
/// subtraction was exact, the range of binary exponents its components span.
#[derive(Clone, Copy, Debug)]
pub struct Dir {
    /// The rounded difference `p − v`.
    pub d: Point3,
    /// Lowest exponent of a set bit over the components (`i32::MAX` if all are zero).
    lo: i32,
    /// Highest exponent over the components, or `i32::MIN` when the subtraction rounded.
    hi: i32,
}

/// Exponents `(lowest set bit, highest set bit)` of a non-zero finite double.
#[inline]
fn bit_span(x: f64) -> (i32, i32) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let mant = (bits & ((1u64 << 52) - 1)) | if exp > 0 { 1u64 << 52 } else { 0 };
    let e = if exp > 0 { exp - 1075 } else { -1074 };
    (
        e + mant.trailing_zeros() as i32,
        e + 63 - mant.leading_zeros() as i32,
    )
}

/// True when `a − b` is computed without rounding (Knuth's TwoDiff error term is zero).
#[inline]
fn exact_diff(a: f64, b: f64) -> bool {
    let x = a - b;
    let bv = a - x;
    let av = x + bv;
    (a - av) + (bv - b) == 0.0
}

/// Orientation tests that share one apex `v`, with a cached floating-point filter.
///
/// `sign(v, a, b, c)` equals [`orient3d`]`(v, a, b, c)` exactly: the float determinant is
/// trusted when it exceeds a proven error bound, or when it is provably computed without
/// any rounding (exact differences whose nine components span at most 15 bits: then every
/// product and sum is exact, which covers grids and other integer data, where exact zeros
/// abound); otherwise the adaptive exact predicate decides.
///
/// ```
/// use tetrakit::geom::{Frame, orient3d};
/// let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let f = Frame::new(&pts[0]);
/// let d: Vec<_> = pts.iter().map(|p| f.dir(p)).collect();
/// assert_eq!(f.sign(&pts[1], &pts[2], &pts[3], &d[1], &d[2], &d[3]), 1);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    v: Point3,
}

impl Frame {
    /// A frame with apex `v`.
    pub fn new(v: &Point3) -> Self {
        Frame { v: *v }
    }
    /// The direction `p − v`, prepared for [`Frame::sign`].
    #[inline]
    pub fn dir(&self, p: &Point3) -> Dir {
        let d = [p[0] - self.v[0], p[1] - self.v[1], p[2] - self.v[2]];
        let (mut lo, mut hi) = (i32::MAX, i32::MIN + 1);
        for k in 0..3 {
            if !exact_diff(p[k], self.v[k]) {
                return Dir {
                    d,
                    lo: i32::MAX,
                    hi: i32::MIN,
                };
            }
            if d[k] != 0.0 {
                let (l, h) = bit_span(d[k]);
                lo = lo.min(l);
                hi = hi.max(h);
            }
        }
        Dir { d, lo, hi }
    }
    /// Exact sign of `orient3d(v, a, b, c)`, given the prepared directions of `a, b, c`.
    #[inline]
    pub fn sign(&self, a: &Point3, b: &Point3, c: &Point3, da: &Dir, db: &Dir, dc: &Dir) -> i8 {
        let (det, perm) = det_perm(&da.d, &db.d, &dc.d);
        let bound = FRAME_ERR * perm;
        if det > bound {
            return 1;
        }
        if det < -bound {
            return -1;
        }
        if computed_exactly(da, db, dc) {
            // Every operation of det_perm was exact.
            return sign(det);
        }
        orient3d(&self.v, a, b, c)
    }
}

/// The plane through the apex `v` and two points `a, b`, prepared for many exact side
/// tests `orient3d(v, a, b, c)` (one dot product each, same rounding as [`Frame::sign`]).
#[derive(Clone, Copy, Debug)]
pub struct ApexPlane {
    n: Point3,
    pm: Point3,
    lo: i32,
    hi: i32,
}

impl Frame {
    /// Prepares the plane through `v` and the points with directions `da`, `db`.
    #[inline]
    pub fn plane(&self, da: &Dir, db: &Dir) -> ApexPlane {
        let (n, pm) = normal(&da.d, &db.d);
        let inexact = da.hi == i32::MIN || db.hi == i32::MIN;
        ApexPlane {
            n,
            pm,
            lo: da.lo.min(db.lo),
            hi: if inexact { i32::MIN } else { da.hi.max(db.hi) },
        }
    }

    /// Exact sign of `orient3d(v, a, b, c)` for the plane `pl` through `v, a, b`.
    #[inline]
    pub fn side(&self, pl: &ApexPlane, a: &Point3, b: &Point3, c: &Point3, dc: &Dir) -> i8 {
        let d = &dc.d;
        let det = d[0] * pl.n[0] + d[1] * pl.n[1] + d[2] * pl.n[2];
        let perm = d[0].abs() * pl.pm[0] + d[1].abs() * pl.pm[1] + d[2].abs() * pl.pm[2];
        let bound = FRAME_ERR * perm;
        // Branch-free on the certain case: signs are unpredictable, certainty is not.
        let (pos, neg) = (det > bound, det < -bound);
        if pos | neg {
            return i8::from(pos) - i8::from(neg);
        }
        let (lo, hi) = (pl.lo.min(dc.lo), pl.hi.max(dc.hi));
        if pl.hi != i32::MIN && dc.hi != i32::MIN && (lo == i32::MAX || hi - lo <= 15) {
            return sign(det);
        }
        orient3d(&self.v, a, b, c)
    }
}

/// The spheres through the apex `v` of a [`Frame`] and two points `b, c`, prepared for
/// many exact in-sphere tests `insphere(v, b, c, q, p)` (see [`Frame::insphere`]).
#[derive(Clone, Copy, Debug)]
pub struct ApexSpheres {
    /// Signed 2×2 minors of the lifted rows of `b` and `c`, in the order that pairs them
    /// with the complementary minors of `q` and `p`.
    m: [f64; 6],
    /// Their permanents (sums of the absolute values of the two products).
    pm: [f64; 6],
}

/// The lifted direction `(d, |d|²)`.
#[inline]
fn lift(d: &Point3) -> [f64; 4] {
    [d[0], d[1], d[2], d[0] * d[0] + d[1] * d[1] + d[2] * d[2]]
}

/// The six 2×2 minors of two lifted rows, columns `(0,1) (0,2) (0,3) (1,2) (1,3) (2,3)`,
/// and their permanents.
#[inline]
fn minors(x: &[f64; 4], y: &[f64; 4]) -> ([f64; 6], [f64; 6]) {
    let pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    let mut m = [0.0; 6];
    let mut pm = [0.0; 6];
    for (k, &(i, j)) in pairs.iter().enumerate() {
        let (p, q) = (x[i] * y[j], x[j] * y[i]);
        m[k] = p - q;
        pm[k] = p.abs() + q.abs();
    }
    (m, pm)
}

/// Bound on the rounding error of [`Frame::insphere`]'s determinant, relative to its
/// permanent: the expansion has degree 5 in rounded differences and about a dozen
/// roundings per term; Shewchuk's bound for the same degree is (16 + 224u)u, we use 64u.
const SPHERE_ERR: f64 = 64.0 * f64::EPSILON / 2.0;

impl Frame {
    /// Prepares the spheres through `v` and the points with directions `db`, `dc`.
    #[inline]
    pub fn spheres(&self, db: &Dir, dc: &Dir) -> ApexSpheres {
        let (m, pm) = minors(&lift(&db.d), &lift(&dc.d));
        // Laplace expansion of the lifted 4×4 determinant by its first two rows: the
        // minor on columns {i, j} pairs with the one on the complement, signed.
        ApexSpheres {
            m: [m[0], -m[1], m[2], m[3], -m[4], m[5]],
            pm: [pm[0], pm[1], pm[2], pm[3], pm[4], pm[5]],
        }
    }

    /// Exact sign of [`insphere`]`(v, b, c, q, p)` for the spheres `s` through `v, b, c`:
    /// +1 when `p` is inside the sphere through the positively oriented `vbcq`.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn insphere(
        &self,
        s: &ApexSpheres,
        b: &Point3,
        c: &Point3,
        q: &Point3,
        p: &Point3,
        dq: &Dir,
        dp: &Dir,
    ) -> i8 {
        let (n, pn) = minors(&lift(&dq.d), &lift(&dp.d));
        // Complementary column pairs: (2,3) (1,3) (1,2) (0,3) (0,2) (0,1).
        let mut det = 0.0;
        let mut perm = 0.0;
        for k in 0..6 {
            det += s.m[k] * n[5 - k];
            perm += s.pm[k] * pn[5 - k];
        }
        let bound = SPHERE_ERR * perm;
        // The lifted determinant is negative when p is inside (for vbcq positive).
        if det > bound {
            return -1;
        }
        if det < -bound {
            return 1;
        }
        insphere(&self.v, b, c, q, p)
    }
}

/// The six products of the cross product `b × c`, in pairs: component `k` is
/// `m[2k] − m[2k + 1]`.
#[inline]
fn products(b: &Point3, c: &Point3) -> [f64; 6] {
    [
        b[1] * c[2],
        b[2] * c[1],
        b[2] * c[0],
        b[0] * c[2],
        b[0] * c[1],
        b[1] * c[0],
    ]
}

/// The rounded cross product `b × c`, component `k` the difference `m[2k] − m[2k + 1]`
/// of [`products`], and each component's permanent `|m[2k]| + |m[2k + 1]|`.
#[inline]
fn normal(b: &Point3, c: &Point3) -> (Point3, Point3) {
    let m = products(b, c);
    let n = [m[0] - m[1], m[2] - m[3], m[4] - m[5]];
    let pm = [
        m[0].abs() + m[1].abs(),
        m[2].abs() + m[3].abs(),
        m[4].abs() + m[5].abs(),
    ];
    (n, pm)
}

/// The float determinant `det[da, db, dc]` and its permanent (for the error bound).
#[inline]
fn det_perm(da: &Point3, db: &Point3, dc: &Point3) -> (f64, f64) {
    let [m0, m1, m2, m3, m4, m5] = products(db, dc);
    let det = da[0] * (m0 - m1) + da[1] * (m2 - m3) + da[2] * (m4 - m5);
    let perm = da[0].abs() * (m0.abs() + m1.abs())
        + da[1].abs() * (m2.abs() + m3.abs())
        + da[2].abs() * (m4.abs() + m5.abs());
    (det, perm)
}

/// The float filter of [`orient3d`]`(a, b, c, x)` for one plane and many points `x`:
/// the rounded normal `(b − a) × (c − a)` is computed once, each component a difference
/// of two products `m[2k] − m[2k + 1]`, with its permanent `|m[2k]| + |m[2k + 1]|`. A test
/// evaluates the same float determinant and permanent as [`Frame`]'s filter, in the same
/// order and with its bound (so with the same decisions); `None` where it does not
/// certify the sign, and the caller asks the exact predicate. The plane's point `a` is
/// the caller's to keep (a hull keeps a filter per triangle: its size is page faults).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PlaneFilter {
    n: Point3,
    pm: Point3,
}

impl PlaneFilter {
    /// The rounded `orient3d(a, b, c, x)` on the stored normal, and `x − a`.
    #[inline]
    fn det(&self, a: &Point3, x: &Point3) -> (f64, Point3) {
        let n = &self.n;
        let dx = [x[0] - a[0], x[1] - a[1], x[2] - a[2]];
        (dx[0] * n[0] + dx[1] * n[1] + dx[2] * n[2], dx)
    }

    /// The filter of the plane through `a, b, c`.
    #[inline]
    pub(crate) fn new(a: &Point3, b: &Point3, c: &Point3) -> Self {
        let db = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let dc = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let (n, pm) = normal(&db, &dc);
        PlaneFilter { n, pm }
    }

    /// The sign of `orient3d(a, b, c, x)` where the filter certifies it (`a` the plane's
    /// first point).
    #[inline]
    pub(crate) fn sign(&self, a: &Point3, x: &Point3) -> Option<i8> {
        let (det, dx) = self.det(a, x);
        let pm = &self.pm;
        let perm = dx[0].abs() * pm[0] + dx[1].abs() * pm[1] + dx[2].abs() * pm[2];
        let bound = FRAME_ERR * perm;
        if det > bound {
            Some(1)
        } else if det < -bound {
            Some(-1)
        } else {
            None
        }
    }
}

/// The oriented plane through `a, b, c`, for many exact side tests against one plane.
///
/// `side(x)` equals [`orient3d`]`(a, b, c, x)`: the float filter of the plane
/// ([`PlaneFilter`], its normal computed once), then the exact predicate where it does
/// not decide.
#[derive(Clone, Copy, Debug)]
pub struct Plane {
    filter: PlaneFilter,
    a: Point3,
    b: Point3,
    c: Point3,
}

impl Plane {
    /// The plane through `a, b, c`.
    pub fn new(a: &Point3, b: &Point3, c: &Point3) -> Self {
        Plane {
            filter: PlaneFilter::new(a, b, c),
            a: *a,
            b: *b,
            c: *c,
        }
    }
    /// Exact sign of `orient3d(a, b, c, x)`.
    #[inline]
    pub fn side(&self, x: &Point3) -> i8 {
        self.filtered(x)
            .unwrap_or_else(|| orient3d(&self.a, &self.b, &self.c, x))
    }
    #[inline]
    fn filtered(&self, x: &Point3) -> Option<i8> {
        self.filter.sign(&self.a, x)
    }
    /// A filter for a whole closed box `[lo, hi]`: `1` when every point of it is strictly
    /// on the positive side (`side` = 1), `-1` when every point is strictly negative, `0`
    /// when the floating-point filter does not certify either (a box meeting the plane
    /// always gets 0). Where it answers it is exact: a box is the convex hull of its
    /// corners, and each corner's sign is certified by the rounding bound of
    /// [`Plane::side`]'s filter; no exact stage runs. When the sign of every component of
    /// the normal is certain (each float component far above its rounding, about
    /// `4ε` of its two products), the corners where the side is least and greatest are
    /// known and only those two are tested.
    pub fn box_side(&self, lo: &Point3, hi: &Point3) -> i8 {
        let (n, pm) = (&self.filter.n, &self.filter.pm);
        let sure = (0..3).all(|k| n[k].abs() > 1e-12 * pm[k]);
        if sure {
            let least: Point3 = std::array::from_fn(|k| if n[k] > 0.0 { lo[k] } else { hi[k] });
            let most: Point3 = std::array::from_fn(|k| if n[k] > 0.0 { hi[k] } else { lo[k] });
            return match (self.filtered(&least), self.filtered(&most)) {
                (Some(1), _) => 1,
                (_, Some(-1)) => -1,
                _ => 0,
            };
        }
        let mut sign = 0;
        for corner in 0..8 {
            let x: Point3 =
                std::array::from_fn(|k| if corner >> k & 1 == 0 { lo[k] } else { hi[k] });
            match self.filtered(&x) {
                Some(s) if sign == 0 || s == sign => sign = s,
                _ => return 0,
            }
        }
        sign
    }
    /// A rounded estimate of the signed distance scale of `x` (for heuristics only).
    pub fn estimate(&self, x: &Point3) -> f64 {
        self.filter.det(&self.a, x).0
    }
}

/// Sign of the counter-clockwise orientation of `a, b, c` in the plane.
///
/// ```
/// use tetrakit::geom::orient2d;
/// assert_eq!(orient2d(&[0.0, 0.0], &[1.0, 0.0], &[0.0, 1.0]), 1);
/// assert_eq!(orient2d(&[0.0, 0.0], &[1.0, 1.0], &[3.0, 3.0]), 0);
/// ```
#[inline]
pub fn orient2d(a: &Point2, b: &Point2, c: &Point2) -> i8 {
    let f = |p: &Point2| Coord { x: p[0], y: p[1] };
    sign(robust::orient2d(f(a), f(b), f(c)))
}

/// [`orient2d`] of the projections of three 3D points that drop coordinate `axis`
/// (the remaining two coordinates keep their order). Dropping a coordinate is exact.
#[inline]
pub fn orient2d_drop(a: &Point3, b: &Point3, c: &Point3, axis: usize) -> i8 {
    orient2d(
        &drop_axis(a, axis),
        &drop_axis(b, axis),
        &drop_axis(c, axis),
    )
}

/// The 2D point left when coordinate `axis` of `p` is dropped.
#[inline]
pub fn drop_axis(p: &Point3, axis: usize) -> Point2 {
    match axis {
        0 => [p[1], p[2]],
        1 => [p[0], p[2]],
        _ => [p[0], p[1]],
    }
}

/// Coplanar points dropped to 2D along an axis their plane is not parallel to, so that
/// orientations are preserved for one fixed normal; `None` when they are collinear (or
/// fewer than three distinct). The orientation of planar triangulations in this crate
/// (counter-clockwise) is taken in this projection.
pub fn project_to_plane(points: &[Point3]) -> Option<Vec<Point2>> {
    let a = points.first()?;
    let b = points.iter().find(|p| *p != a)?;
    let c = points.iter().find(|c| projection_axis(a, b, c).is_some())?;
    let axis = projection_axis(a, b, c)?;
    Some(points.iter().map(|p| drop_axis(p, axis)).collect())
}

/// True when three points lie on one line (exact).
pub fn collinear3(a: &Point3, b: &Point3, c: &Point3) -> bool {
    (0..3).all(|ax| orient2d_drop(a, b, c, ax) == 0)
}

/// An axis whose dropping keeps the triangle `abc` non-degenerate, if `abc` is not
/// collinear. Every point of the plane of `abc` then projects injectively.
pub fn projection_axis(a: &Point3, b: &Point3, c: &Point3) -> Option<usize> {
    (0..3).rev().find(|&ax| orient2d_drop(a, b, c, ax) != 0)
}

/// Sign of the in-sphere test: +1 when `e` is inside the sphere through the positively
/// oriented tetrahedron `abcd`.
///
/// Where `e` and three of `a, b, c, d` lie in a plane `x_k = h` (the same coordinate
/// `k`, equal as floats), the test is a 2D in-circle test (the lifted determinant
/// expanded along that column): exactly the same sign, at a fraction of the cost where
/// the points are also nearly cocircular (Bern disks' ridge: a cocircular polygon in
/// `z = 0`).
pub fn insphere(a: &Point3, b: &Point3, c: &Point3, d: &Point3, e: &Point3) -> i8 {
    // robust::insphere is positive for e inside when robust::orient3d(a,b,c,d) > 0,
    // which is our negative orientation; swapping a and b converts conventions.
    if let Some(s) = insphere_filtered(b, a, c, d, e) {
        return s;
    }
    if let Some(s) = insphere_on_axis_plane([a, b, c, d], e) {
        return s;
    }
    sign(robust::insphere(c3(b), c3(a), c3(c), c3(d), c3(e)))
}

/// The first stage of `robust::insphere` (Shewchuk's stage A, the same expressions and
/// error bound): the sign of the float determinant where its error bound certifies it,
/// `None` where the exact stages would run.
#[inline]
fn insphere_filtered(
    pa: &Point3,
    pb: &Point3,
    pc: &Point3,
    pd: &Point3,
    pe: &Point3,
) -> Option<i8> {
    const EPS: f64 = f64::EPSILON / 2.0;
    const ISPERRBOUND_A: f64 = (16.0 + 224.0 * EPS) * EPS;
    let [a, b, c, d] = [pa, pb, pc, pd].map(|p| [p[0] - pe[0], p[1] - pe[1], p[2] - pe[2]]);
    let (aexbey, bexaey) = (a[0] * b[1], b[0] * a[1]);
    let (bexcey, cexbey) = (b[0] * c[1], c[0] * b[1]);
    let (cexdey, dexcey) = (c[0] * d[1], d[0] * c[1]);
    let (dexaey, aexdey) = (d[0] * a[1], a[0] * d[1]);
    let (aexcey, cexaey) = (a[0] * c[1], c[0] * a[1]);
    let (bexdey, dexbey) = (b[0] * d[1], d[0] * b[1]);
    let (ab, bc, cd) = (aexbey - bexaey, bexcey - cexbey, cexdey - dexcey);
    let (da, ac, bd) = (dexaey - aexdey, aexcey - cexaey, bexdey - dexbey);
    let abc = a[2] * bc - b[2] * ac + c[2] * ab;
    let bcd = b[2] * cd - c[2] * bd + d[2] * bc;
    let cda = c[2] * da + d[2] * ac + a[2] * cd;
    let dab = d[2] * ab + a[2] * bd + b[2] * da;
    let lift = |p: &Point3| p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    let (alift, blift, clift, dlift) = (lift(&a), lift(&b), lift(&c), lift(&d));
    let det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    let (az, bz, cz, dz) = (a[2].abs(), b[2].abs(), c[2].abs(), d[2].abs());
    let pab = aexbey.abs() + bexaey.abs();
    let pbc = bexcey.abs() + cexbey.abs();
    let pcd = cexdey.abs() + dexcey.abs();
    let pda = dexaey.abs() + aexdey.abs();
    let pac = aexcey.abs() + cexaey.abs();
    let pbd = bexdey.abs() + dexbey.abs();
    let permanent = (pcd * bz + pbd * cz + pbc * dz) * alift
        + (pda * cz + pac * dz + pcd * az) * blift
        + (pab * dz + pbd * az + pda * bz) * clift
        + (pbc * az + pac * bz + pab * cz) * dlift;
    let bound = ISPERRBOUND_A * permanent;
    (det > bound || -det > bound).then(|| sign(det))
}

/// [`insphere`] where `e` and three of the four points `q` share a coordinate `k`;
/// `None` otherwise.
///
/// With the rows taken relative to `e`, the lifted `4 × 4` determinant has column `k`
/// zero but in the row of the fourth point `d` (the one off the plane), and the lift
/// `|p − e|²` of the three others is their 2D lift in the plane. Expanding along column
/// `k`, its sign is that of `d_k − e_k` times the in-circle determinant of the three
/// and `e`, projected by dropping coordinate `k` (the other two taken cyclically, so that
/// the sign does not depend on `k`). Both factors are exact signs; when all four share
/// the coordinate, the column is zero and so is the determinant.
fn insphere_on_axis_plane(q: [&Point3; 4], e: &Point3) -> Option<i8> {
    let (k, off) = (0..3).find_map(|k| {
        let mut off = q.iter().enumerate().filter(|(_, p)| p[k] != e[k]);
        match (off.next(), off.next()) {
            (None, _) => Some((k, None)),
            (Some((j, _)), None) => Some((k, Some(j))),
            _ => None,
        }
    })?;
    let Some(j) = off else {
        return Some(0);
    };
    // Move the point off the plane last: a transposition changes the sign.
    let mut q = q;
    q.swap(j, 3);
    let flip = if j == 3 { 1 } else { -1 };
    let drop = |p: &Point3| Coord {
        x: p[(k + 1) % 3],
        y: p[(k + 2) % 3],
    };
    let circle = sign(robust::incircle(
        drop(q[0]),
        drop(q[1]),
        drop(q[2]),
        drop(e),
    ));
    let height = sign(q[3][k] - e[k]);
    Some(flip * height * circle)
}

/// Sign of the in-circle test: +1 when `d` is inside the circle through the
/// counter-clockwise triangle `abc`.
pub fn incircle(a: &Point2, b: &Point2, c: &Point2, d: &Point2) -> i8 {
    let f = |p: &Point2| Coord { x: p[0], y: p[1] };
    sign(robust::incircle(f(a), f(b), f(c), f(d)))
}

/// The axis-aligned bounding box `(lo, hi)` of a point set in 2D or 3D (infinite bounds
/// when empty).
///
/// ```
/// use tetrakit::geom::bounding_box;
/// assert_eq!(bounding_box(&[[1.0, 5.0], [3.0, 2.0]]), ([1.0, 2.0], [3.0, 5.0]));
/// assert_eq!(bounding_box(&[[0.0, 1.0, 2.0]]).1, [0.0, 1.0, 2.0]);
/// ```
pub fn bounding_box<const N: usize>(points: &[[f64; N]]) -> ([f64; N], [f64; N]) {
    let (mut lo, mut hi) = ([f64::INFINITY; N], [f64::NEG_INFINITY; N]);
    for p in points {
        for k in 0..N {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

/// Lexicographic comparison of points (exact), consistent with `==` on points: `-0.0`
/// and `0.0` compare equal (`total_cmp` alone would put every `-0.0` before every
/// `0.0`, so that equal points need not be neighbours in a sorted list and a tie on `x`
/// at zero would not be decided by `y`). The coordinates are finite (the readers refuse
/// NaN).
pub fn lex_cmp(a: &Point3, b: &Point3) -> std::cmp::Ordering {
    let key = |x: f64| x + 0.0;
    key(a[0])
        .total_cmp(&key(b[0]))
        .then(key(a[1]).total_cmp(&key(b[1])))
        .then(key(a[2]).total_cmp(&key(b[2])))
}

/// For three collinear points (2D or 3D), true when `p` lies strictly between `a` and `b`.
pub fn strictly_between<const N: usize>(a: &[f64; N], p: &[f64; N], b: &[f64; N]) -> bool {
    (0..N).any(|k| (a[k] < p[k] && p[k] < b[k]) || (b[k] < p[k] && p[k] < a[k]))
}

#[cfg(test)]
mod tests {
    /// A plane's filter answers only with `orient3d`'s sign, and the exact stages alone
    /// (`orient3d_unfiltered`) give it too: small integers (coplanar and repeated points
    /// common) and floats.
    #[test]
    fn plane_filters_and_exact_stages_agree_with_orient3d() {
        use super::{PlaneFilter, Point3, orient3d, orient3d_unfiltered};
        let mut rng = crate::rng::Rng::new(17);
        let mut answered = 0;
        for case in 0..40_000 {
            let mut point = || -> Point3 {
                match case % 2 {
                    0 => [0; 3].map(|_| rng.below(4) as f64),
                    _ => [0; 3].map(|_| rng.unit() * 3.0),
                }
            };
            let (a, b, c, x) = (point(), point(), point(), point());
            let exact = orient3d(&a, &b, &c, &x);
            assert_eq!(
                orient3d_unfiltered(&a, &b, &c, &x),
                exact,
                "{a:?} {b:?} {c:?} {x:?}"
            );
            if let Some(s) = PlaneFilter::new(&a, &b, &c).sign(&a, &x) {
                assert_eq!(s, exact, "{a:?} {b:?} {c:?} {x:?}");
                answered += 1;
            }
        }
        assert!(answered > 20_000, "{answered}");
    }

    /// The in-sphere test through an axis plane agrees with the full 4 × 4 test
    /// (`robust::insphere`) on every configuration it answers: integer points with `e`
    /// and three others (or all four) in a plane `x_k = h`, the off-plane point at each of
    /// the four places, and nearly cocircular float points on the unit circle in `z = 0`
    /// (Bern disks' ridge), where both tests go past their float filters.
    #[test]
    fn insphere_through_an_axis_plane_is_the_full_test() {
        use super::{Point3, c3, insphere_on_axis_plane, sign};
        let mut rng = crate::rng::Rng::new(41);
        let (mut answered, mut signs) = (0, [0usize; 3]);
        for case in 0..60_000 {
            let k = case % 3;
            let h = rng.below(3) as f64;
            let cocircular = case % 4 == 3;
            let off = rng.below(5);
            let mut point = |on: bool| -> Point3 {
                let mut p: Point3 = match cocircular {
                    true => {
                        let t = rng.unit() * std::f64::consts::TAU;
                        let z = if on { 0.0 } else { (rng.unit() - 0.5) * 0.1 };
                        [t.cos(), t.sin(), z]
                    }
                    false => [0; 3].map(|_| rng.below(4) as f64),
                };
                if on && !cocircular {
                    p[k] = h;
                }
                p
            };
            let e = point(true);
            let q: [Point3; 4] = std::array::from_fn(|i| point(i != off));
            let full = sign(robust::insphere(
                c3(&q[1]),
                c3(&q[0]),
                c3(&q[2]),
                c3(&q[3]),
                c3(&e),
            ));
            let found = insphere_on_axis_plane([&q[0], &q[1], &q[2], &q[3]], &e);
            if let Some(s) = found {
                assert_eq!(s, full, "case {case}: {q:?} {e:?}");
                answered += 1;
                signs[(s + 1) as usize] += 1;
            }
            assert_eq!(super::insphere(&q[0], &q[1], &q[2], &q[3], &e), full);
        }
        assert!(
            answered > 50_000 && signs.iter().all(|&n| n > 1000),
            "{answered} {signs:?}"
        );
    }

    /// `Plane::box_side` answers only where every corner has that exact sign, and it
    /// answers for boxes clear of the plane: random planes (small integers, so many
    /// boxes touch them exactly, and random floats) against random boxes.
    #[test]
    fn box_side_is_every_corners_sign() {
        use crate::geom::{Plane, orient3d};
        let mut rng = crate::rng::Rng::new(9);
        let (mut clear, mut answered) = (0, 0);
        for case in 0..20_000 {
            let mut point = || -> super::Point3 {
                if case % 2 == 0 {
                    [0; 3].map(|_| rng.below(9) as f64)
                } else {
                    [0; 3].map(|_| rng.unit() * 8.0)
                }
            };
            let (a, b, c, x, y) = (point(), point(), point(), point(), point());
            let lo: super::Point3 = std::array::from_fn(|k| x[k].min(y[k]));
            let hi: super::Point3 = std::array::from_fn(|k| x[k].max(y[k]));
            let plane = Plane::new(&a, &b, &c);
            let corners: Vec<i8> = (0..8)
                .map(|m| {
                    let p = std::array::from_fn(|k| if m >> k & 1 == 0 { lo[k] } else { hi[k] });
                    orient3d(&a, &b, &c, &p)
                })
                .collect();
            let side = plane.box_side(&lo, &hi);
            if side != 0 {
                answered += 1;
                assert!(
                    corners.iter().all(|&s| s == side),
                    "{a:?} {b:?} {c:?} {lo:?} {hi:?}"
                );
            }
            if corners[0] != 0 && corners.iter().all(|&s| s == corners[0]) {
                clear += 1;
            }
        }
        // Every box clear of the plane is certified (only near-zero corners fall to the
        // exact stage, and clear integer boxes have none).
        assert!(answered * 100 >= clear * 99, "{answered} of {clear}");
    }

    /// `Plane` on a worked example.
    #[test]
    fn plane_example() {
        use crate::geom::Plane;
        let p = Plane::new(&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0], &[0.0, 1.0, 0.0]);
        assert_eq!(p.side(&[3.0, 3.0, 1.0]), 1);
        assert_eq!(p.side(&[3.0, 3.0, 0.0]), 0);
    }

    /// `project_to_plane` on a worked example.
    #[test]
    fn project_to_plane_example() {
        use crate::geom::project_to_plane;
        let p = project_to_plane(&[[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]]).unwrap();
        assert_eq!(p[1], [1.0, 0.0]);
        assert!(project_to_plane(&[[0.0; 3], [1.0; 3], [2.0; 3]]).is_none());
    }

    /// `strictly_between` on a worked example.
    #[test]
    fn strictly_between_example() {
        use crate::geom::strictly_between;
        assert!(strictly_between(&[0.0, 4.0], &[0.0, 3.0], &[0.0, 1.0]));
        assert!(!strictly_between(
            &[0.0, 0.0, 0.0],
            &[2.0, 2.0, 2.0],
            &[1.0, 1.0, 1.0]
        ));
    }

    use super::*;

    #[test]
    fn lex_cmp_ties_signed_zeros() {
        use std::cmp::Ordering;
        assert_eq!(
            lex_cmp(&[-0.0, 5.0, 0.0], &[0.0, 1.0, 0.0]),
            Ordering::Greater
        );
        assert_eq!(
            lex_cmp(&[-0.0, 1.0, 0.0], &[0.0, 1.0, -0.0]),
            Ordering::Equal
        );
    }

    #[test]
    fn orient3d_convention_matches_tetgen() {
        let a = [0.0, 0.0, 0.0];
        let b = [1.0, 0.0, 0.0];
        let c = [0.0, 1.0, 0.0];
        let d = [0.0, 0.0, 1.0];
        assert_eq!(orient3d(&a, &b, &c, &d), 1);
        assert_eq!(orient3d(&b, &a, &c, &d), -1);
        assert_eq!(orient3d(&a, &b, &c, &[3.0, -2.0, 0.0]), 0);
    }

    #[test]
    fn orient3d_exact_on_nearly_coplanar_points() {
        // The plane x + y + z = 1; offsets of one ulp decide the sign.
        let a = [1.0, 0.0, 0.0];
        let b = [0.0, 1.0, 0.0];
        let c = [0.0, 0.0, 1.0];
        let up = 0.5 + f64::EPSILON / 2.0;
        let down = 0.5 - f64::EPSILON / 4.0;
        assert_eq!(orient3d(&a, &b, &c, &[0.25, 0.25, 0.5]), 0);
        assert_eq!(orient3d(&a, &b, &c, &[0.25, 0.25, up]), 1);
        assert_eq!(orient3d(&a, &b, &c, &[0.25, 0.25, down]), -1);
        let f = Frame::new(&a);
        for (z, s) in [(0.5, 0), (up, 1), (down, -1)] {
            let d = [0.25, 0.25, z];
            assert_eq!(f.sign(&b, &c, &d, &f.dir(&b), &f.dir(&c), &f.dir(&d)), s);
            assert_eq!(Plane::new(&a, &b, &c).side(&d), s);
        }
    }

    #[test]
    fn orient3d_agrees_with_robust_on_axis_planes() {
        // Quadruples with a shared coordinate (exact zeros), one point off the plane by
        // an ulp (the shortcut must not answer there), across the coordinate range.
        let mut rng = crate::rng::Rng::new(17);
        let mut zeros = 0;
        for k in 0..20_000 {
            let axis = k % 3;
            let scale = [1e-40, 1e-3, 1.0, 7.0, 1e50][k % 5];
            let level = (rng.below(9) as f64 - 4.0) * scale / 3.0;
            let mut q = [[0.0; 3]; 4].map(|_| {
                let mut p = [0.0; 3].map(|_| (rng.below(2001) as f64 - 1000.0) * scale / 7.0);
                p[axis] = level;
                p
            });
            // None of the four, or one of them, an ulp off the plane; every other time the
            // other three nearly collinear (the middle one an ulp off the segment of the
            // two others), where the filter fails.
            let off = [None, Some(0), Some(1), Some(2), Some(3)][(k / 5) % 5];
            if k % 2 == 1 {
                let [i, j, l] = match off {
                    Some(o) => [0, 1, 2, 3].map(|x| (o + 1 + x) % 4)[..3]
                        .try_into()
                        .unwrap(),
                    None => [1, 2, 3],
                };
                let mid = [0, 1, 2].map(|x| q[i][x] + (q[l][x] - q[i][x]) / 2.0);
                let along = (axis + 1) % 3;
                q[j] = mid;
                q[j][along] = f64::from_bits(mid[along].to_bits() + 1);
            }
            if let Some(o) = off {
                q[o][axis] = f64::from_bits(level.to_bits() + 1);
            }
            let want = -sign(robust::orient3d(c3(&q[0]), c3(&q[1]), c3(&q[2]), c3(&q[3])));
            let got = orient3d(&q[0], &q[1], &q[2], &q[3]);
            assert_eq!(got, want, "{q:?}");
            zeros += usize::from(got == 0);
        }
        assert!(zeros > 3_000, "{zeros}");
    }

    #[test]
    fn determinants_computed_exactly_are_exact() {
        // Integers of 4 to 19 bits (spans on both sides of the 15-bit bound) times a power
        // of two: wherever `computed_exactly` says so, both float evaluations equal the
        // determinant in 128-bit integers (counted in units of the power of two).
        let mut rng = crate::rng::Rng::new(23);
        let mut accepted = [0; 2];
        for k in 0..40_000 {
            let bits = 4 + (k % 16) as u32;
            let e = [0, -1, -30, 40][(k / 16) % 4];
            let mut int = || rng.below(1 << bits) as i64 - (1 << (bits - 1));
            let rows = [0; 3].map(|_| [int(), int(), int()]);
            let [a, b, c] = rows.map(|r| r.map(|x| x as f64 * 2f64.powi(e)));
            let f = Frame::new(&[0.0; 3]);
            if !computed_exactly(&f.dir(&a), &f.dir(&b), &f.dir(&c)) {
                accepted[1] += 1;
                continue;
            }
            accepted[0] += 1;
            let m = rows.map(|r| r.map(i128::from));
            let exact = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
            let unit = 2f64.powi(3 * e);
            for det in [shewchuk_det(&a, &b, &c).0, det_perm(&a, &b, &c).0] {
                assert_eq!(det / unit, exact as f64, "{rows:?} at 2^{e}");
                assert_eq!(det / unit, (det / unit).round());
            }
        }
        assert!(accepted.iter().all(|&n| n > 2_000), "{accepted:?}");
    }

    #[test]
    fn frame_filter_agrees_with_exact_predicate_on_degenerate_grid() {
        // All points of a small grid: most quadruples are coplanar.
        let mut pts = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                for k in 0..3 {
                    pts.push([i as f64 * 0.1, j as f64 * 0.3, k as f64 * 0.7]);
                }
            }
        }
        for v in &pts[..5] {
            let f = Frame::new(v);
            for a in &pts {
                for b in pts.iter().step_by(3) {
                    for c in pts.iter().step_by(2) {
                        let s = f.sign(a, b, c, &f.dir(a), &f.dir(b), &f.dir(c));
                        assert_eq!(s, orient3d(v, a, b, c));
                    }
                }
            }
        }
    }

    #[test]
    fn frame_exact_path_never_disagrees() {
        // Integer grids take the no-rounding path; decimals and wide spans must not.
        let mut rng = crate::rng::Rng::new(9);
        let mut pick = |k: usize| -> Point3 {
            match k % 3 {
                0 => [
                    rng.below(5) as f64,
                    rng.below(5) as f64,
                    rng.below(5) as f64,
                ],
                1 => [
                    rng.below(5) as f64 * 0.1,
                    rng.below(5) as f64 * 0.1,
                    rng.below(5) as f64 * 0.1,
                ],
                _ => [
                    rng.below(5) as f64 * 1e9 + 0.5,
                    rng.below(3) as f64,
                    rng.below(5) as f64 * 3e-7,
                ],
            }
        };
        for k in 0..30000 {
            let v = pick(k);
            let [a, b, c] = [pick(k), pick(k), pick(k)];
            let f = Frame::new(&v);
            let s = f.sign(&a, &b, &c, &f.dir(&a), &f.dir(&b), &f.dir(&c));
            assert_eq!(s, orient3d(&v, &a, &b, &c), "{v:?} {a:?} {b:?} {c:?}");
            let pl = f.plane(&f.dir(&a), &f.dir(&b));
            assert_eq!(f.side(&pl, &a, &b, &c, &f.dir(&c)), s);
        }
    }

    #[test]
    fn orient2d_and_collinearity() {
        assert_eq!(orient2d(&[0.0, 0.0], &[1.0, 0.0], &[2.0, 0.0]), 0);
        assert!(collinear3(
            &[0.0, 0.0, 0.0],
            &[1.0, 2.0, 3.0],
            &[2.0, 4.0, 6.0]
        ));
        assert!(!collinear3(
            &[0.0, 0.0, 0.0],
            &[1.0, 2.0, 3.0],
            &[2.0, 4.0, 6.5]
        ));
        assert_eq!(
            projection_axis(&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0], &[0.0, 0.0, 1.0]),
            Some(1)
        );
    }

    #[test]
    fn insphere_and_incircle_conventions() {
        let a = [0.0, 0.0, 0.0];
        let b = [1.0, 0.0, 0.0];
        let c = [0.0, 1.0, 0.0];
        let d = [0.0, 0.0, 1.0];
        assert_eq!(insphere(&a, &b, &c, &d, &[0.2, 0.2, 0.2]), 1);
        assert_eq!(insphere(&a, &b, &c, &d, &[5.0, 5.0, 5.0]), -1);
        assert_eq!(insphere(&a, &b, &c, &d, &[1.0, 1.0, 0.0]), 0); // cospherical
        assert_eq!(
            incircle(&[0.0, 0.0], &[1.0, 0.0], &[0.0, 1.0], &[0.5, 0.5]),
            1
        );
        assert_eq!(
            incircle(&[0.0, 0.0], &[1.0, 0.0], &[0.0, 1.0], &[1.0, 1.0]),
            0
        );
    }

    #[test]
    fn apex_spheres_agree_with_insphere() {
        let mut rng = crate::rng::Rng::new(3);
        let mut coord = |grid: bool| {
            if grid {
                rng.below(3) as f64
            } else {
                rng.unit() * 4.0 - 2.0
            }
        };
        let (mut inside, mut on) = (0, 0);
        for case in 0..20_000 {
            let grid = case % 2 == 0;
            let pts: Vec<Point3> = (0..5)
                .map(|_| [coord(grid), coord(grid), coord(grid)])
                .collect();
            let f = Frame::new(&pts[0]);
            let d: Vec<Dir> = pts.iter().map(|p| f.dir(p)).collect();
            let s = f.spheres(&d[1], &d[2]);
            let got = f.insphere(&s, &pts[1], &pts[2], &pts[3], &pts[4], &d[3], &d[4]);
            let want = insphere(&pts[0], &pts[1], &pts[2], &pts[3], &pts[4]);
            assert_eq!(got, want, "{pts:?}");
            inside += usize::from(want == 1);
            on += usize::from(want == 0);
        }
        assert!(inside > 1000 && on > 1000, "{inside} {on}");
    }

    #[test]
    fn coordinate_range() {
        assert!(coordinate_in_range(MAX_MAGNITUDE) && coordinate_in_range(-MIN_MAGNITUDE));
        assert!(!coordinate_in_range(MIN_MAGNITUDE / 2.0));
        assert!(!coordinate_in_range(f64::INFINITY));
    }
}
