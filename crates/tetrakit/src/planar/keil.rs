//! The counterexample to Keil's conjecture (thesis §5.2–5.3): for
//! β ∈ [2/√3, √(2√3+45)/6) a point set whose β-skeleton edge `xy` is in no minimum
//! weight triangulation.
//!
//! **Construction.** `x = (-1, 0)`, `y = (1, 0)`. The points `p, q, r, s` of Lemma 5.3
//! (Cheng and Xu) lie on the circles through `x, y` of diameter `β₁|xy|`,
//! `β₁ = √(2√3+9)/3`: `p = (-u, v)`, `r = (u, v)` with `∠xpr = θ`, `cos θ = (√3-1)/2`,
//! `x ∈ pq`, `y ∈ rs`, mirror symmetric. `q'` and `s'` are where `xq` and `ys` meet the
//! β-circle below `xy`; they are moved outward by ulps until the exact test says they are
//! not strictly inside, so `xy` stays a β-skeleton edge. The `n` sites `r_i` lie on a
//! curve from near `r` (on the hull) down towards `y`, left of the line `s'yr` (so that
//! `s'r_i` crosses `xy`) and bent so that the fans from `s'` and from `y` do not cross
//! (Lemma 5.5(i)), within `δ/2` of `r`, with `δ` the thesis's `½ min{|ss'|, |pr| - |py|, |pr| + |py| - 2|pq'|}` (also kept
//! below the distance from `r` to the β-circle); the `p_i` are their mirror images (exact
//! in floating point, so the mirror ties are exact ties). `n` defaults to one more than
//! Lemma 5.8's bound.
//!
//! The floating-point construction is only a proposal: the verdicts are computed on the
//! actual sites by the exact skeleton test and the exact MWT, with the constrained
//! optimum "with `xy`" for comparison, so what is reported is proven for these sites.

use super::{MwtOptions, PlanarError, cmp_edge_sets, mwt, mwt_with};
use crate::geom::{Interval, Point2, Ratio, in_beta_region};
use std::cmp::Ordering;

/// The lower end of the construction's interval, `2/√3` (Keil's conjectured value):
/// `β ≥ 2/√3 ⟺ 3β² ≥ 4`.
pub fn in_keil_interval(beta: Ratio) -> bool {
    // upper: β < √(2√3+45)/6 ⟺ 36β² - 45 < 2√3 ⟺ t < 0 or t² < 12, t = 36β² - 45.
    let lower = beta.square_cmp(4, 3) != Ordering::Less;
    let (a, b) = (beta.num as i128, beta.den as i128);
    let t_num = 36 * a * a - 45 * b * b; // t = t_num / b²
    let upper = t_num < 0 || {
        let t = t_num as f64 / (b * b) as f64;
        // t² < 12 decided exactly in 128-bit when the numbers fit, else in f64 with margin
        match (t_num.checked_mul(t_num), (b * b).checked_mul(b * b)) {
            (Some(l), Some(r)) if r.checked_mul(12).is_some() => l < 12 * r,
            _ => t * t < 12.0 * (1.0 - 1e-12),
        }
    };
    lower && upper
}

/// Largest site count for the constrained optima, which use all `O(n²)` segments.
pub const CONSTRAINED_LIMIT: usize = 160;

/// The Keil point set and what was found on it.
#[derive(Clone, Debug)]
pub struct KeilResult {
    /// β used.
    pub beta: Ratio,
    /// The sites: `q', x, p_n..p_1, r_1..r_n, y, s'` in this order.
    pub sites: Vec<Point2>,
    /// Indices of `x` and `y`.
    pub xy: [u32; 2],
    /// `n`, the number of sites on each arc.
    pub n: usize,
    /// Lemma 5.8's bound on `n` (computed in floating point).
    pub lemma_bound: f64,
    /// `xy` is an edge of the (circle-based) β-skeleton (exact).
    pub xy_in_skeleton: bool,
    /// `xy` is an edge of the minimum weight triangulation (exact).
    pub xy_in_mwt: bool,
    /// The minimum weight triangulation.
    pub mwt: Vec<[u32; 2]>,
    /// Weight of the best triangulation containing `xy`, and its edges.
    pub with_xy: (Interval, Vec<[u32; 2]>),
    /// Weight of the best triangulation without `xy`, and its edges.
    pub without_xy: (Interval, Vec<[u32; 2]>),
    /// Exact comparison of the two: `Greater` when containing `xy` costs more.
    pub with_vs_without: Ordering,
}

fn dist(a: Point2, b: Point2) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Second intersection of the ray from `from` (on the circle) towards `to` with the
/// circle of centre `c` and radius `rad`.
fn ray_circle(from: Point2, to: Point2, c: Point2, rad: f64) -> Point2 {
    let d = [to[0] - from[0], to[1] - from[1]];
    let f = [from[0] - c[0], from[1] - c[1]];
    let a = d[0] * d[0] + d[1] * d[1];
    let b = 2.0 * (f[0] * d[0] + f[1] * d[1]);
    let cc = f[0] * f[0] + f[1] * f[1] - rad * rad;
    let disc = (b * b - 4.0 * a * cc).max(0.0).sqrt();
    let t = (-b + disc) / (2.0 * a);
    let t = if t.abs() < 1e-12 {
        (-b - disc) / (2.0 * a)
    } else {
        t
    };
    [from[0] + t * d[0], from[1] + t * d[1]]
}

/// Nudges `pt` along `dir` by ulps until it is not strictly inside the β-region of `xy`.
fn outside(mut pt: Point2, dir: Point2, x: &Point2, y: &Point2, beta: Ratio) -> Point2 {
    let mut step = 1e-15;
    while in_beta_region(x, y, &pt, beta) {
        pt = [pt[0] + step * dir[0], pt[1] + step * dir[1]];
        step *= 2.0;
    }
    pt
}

/// The default search for `n` stops here (the exact MWT of the clustered sites grows
/// quickly with `n`; Lemma 5.8's bound is often in the hundreds).
pub const DEFAULT_N_CAP: usize = 64;

/// The best triangulation containing `xy`, for `x`, `y` on the hull and no other site on
/// the line `xy`: the chord splits the hull into two convex regions whose triangulations
/// are those of the sites on each side plus `x` and `y`, so it is the union of two
/// unconstrained MWTs (the diamond test applies to each). Otherwise the constrained
/// solver over all segments.
fn best_with_chord(sites: &[Point2], xy: [u32; 2]) -> Result<super::Mwt, PlanarError> {
    let (x, y) = (&sites[xy[0] as usize], &sites[xy[1] as usize]);
    let hull = crate::geom::Hull2::new(sites);
    let side: Vec<i8> = sites
        .iter()
        .map(|p| crate::geom::orient2d(x, y, p))
        .collect();
    let on_line = (0..sites.len()).any(|i| side[i] == 0 && i as u32 != xy[0] && i as u32 != xy[1]);
    let on_hull = hull.vertices.contains(&xy[0]) && hull.vertices.contains(&xy[1]);
    if on_line || !on_hull {
        return mwt_with(
            sites,
            &MwtOptions {
                forced: vec![xy],
                ..Default::default()
            },
        );
    }
    let mut edges = vec![xy];
    for sign in [1i8, -1] {
        let ids: Vec<u32> = (0..sites.len() as u32)
            .filter(|&i| side[i as usize] == sign || i == xy[0] || i == xy[1])
            .collect();
        if ids.len() < 3 {
            continue;
        }
        let pts: Vec<Point2> = ids.iter().map(|&i| sites[i as usize]).collect();
        for e in mwt(&pts)?.edges {
            let (a, b) = (ids[e[0] as usize], ids[e[1] as usize]);
            edges.push([a.min(b), a.max(b)]);
        }
    }
    edges.sort_unstable();
    edges.dedup();
    let weight = super::weight_of(sites, &edges);
    Ok(super::Mwt {
        edges,
        weight,
        ..Default::default()
    })
}

/// The smallest `n ≤ cap` with `ok(n)`, assuming monotonicity, by doubling then
/// bisection (`cap` when none is found below it).
fn smallest_n(
    cap: usize,
    ok: impl Fn(usize) -> Result<bool, PlanarError>,
) -> Result<usize, PlanarError> {
    let mut hi = 1;
    while hi < cap && !ok(hi)? {
        hi *= 2;
    }
    if hi >= cap {
        return Ok(cap);
    }
    let mut lo = hi / 2 + 1;
    while lo < hi {
        let mid = (lo + hi) / 2;
        if ok(mid)? { hi = mid } else { lo = mid + 1 }
    }
    Ok(hi)
}

/// Builds the construction for `beta` with `n` sites per arc (`None`: Lemma 5.8's
/// smallest `n` whose exact MWT avoids `xy`, at most Lemma 5.8's bound plus one) and
/// decides everything exactly.
pub fn keil(beta: Ratio, n: Option<usize>) -> Result<KeilResult, PlanarError> {
    let (build, lemma_bound) = construction(beta)?;
    let (x, y) = ([-1.0, 0.0], [1.0, 0.0]);
    let bound_n = lemma_bound.max(0.0).floor() as usize + 1;
    // Without a given n: the smallest power of two (then bisected) whose exact MWT
    // avoids xy, never beyond Lemma 5.8's bound (where the thesis proves it must).
    let n = match n {
        Some(n) => n.max(1),
        None => smallest_n(bound_n.min(DEFAULT_N_CAP), |n| {
            let sites = build(n);
            Ok(mwt(&sites)?
                .edges
                .binary_search(&[1, (2 * n + 2) as u32])
                .is_err())
        })?,
    };
    let sites = build(n);
    let xy = [1u32, (2 * n + 2) as u32];
    let xy_in_skeleton = (0..sites.len()).all(|i| {
        i as u32 == xy[0] || i as u32 == xy[1] || !in_beta_region(&x, &y, &sites[i], beta)
    });
    let best = mwt(&sites)?;
    let xy_in_mwt = best.edges.binary_search(&xy).is_ok();
    let forced = best_with_chord(&sites, xy)?;
    if xy_in_mwt && sites.len() > CONSTRAINED_LIMIT {
        return Err(PlanarError::new(format!(
            "{} sites and xy is in the MWT: the best triangulation without xy is computed over all segments, limited to {CONSTRAINED_LIMIT} sites; use a smaller --n",
            sites.len()
        )));
    }
    let other = if xy_in_mwt {
        mwt_with(
            &sites,
            &MwtOptions {
                forbidden: vec![xy],
                ..Default::default()
            },
        )?
    } else {
        best.clone()
    };
    let with_vs_without = cmp_edge_sets(&sites, &forced.edges, &other.edges);
    Ok(KeilResult {
        beta,
        sites,
        xy,
        n,
        lemma_bound,
        xy_in_skeleton,
        xy_in_mwt,
        mwt: best.edges,
        with_xy: (forced.weight, forced.edges),
        without_xy: (other.weight, other.edges),
        with_vs_without,
    })
}

/// The sites of the construction for `beta` with `n` sites per arc.
///
/// ```
/// let sites = tetrakit::planar::keil_sites("1.16".parse().unwrap(), 5).unwrap();
/// assert_eq!(sites.len(), 14);
/// ```
pub fn keil_sites(beta: Ratio, n: usize) -> Result<Vec<Point2>, PlanarError> {
    Ok(construction(beta)?.0(n.max(1)))
}

/// The site builder (sites for a given `n`) and Lemma 5.8's bound on `n`.
#[allow(clippy::type_complexity)]
fn construction(beta: Ratio) -> Result<(Box<dyn Fn(usize) -> Vec<Point2>>, f64), PlanarError> {
    if !in_keil_interval(beta) {
        return Err(PlanarError::new(format!(
            "β = {beta} is outside [2/√3, √(2√3+45)/6) ≈ [1.154701, 1.160274): the construction of §5.2 does not apply"
        )));
    }
    let (x, y) = ([-1.0, 0.0], [1.0, 0.0]);
    let s3 = 3f64.sqrt();
    let b1 = (2.0 * s3 + 9.0).sqrt() / 3.0;
    let (r1, h1) = (b1, (b1 * b1 - 1.0).sqrt());
    let (ct, st) = ((s3 - 1.0) / 2.0, (2.0 * s3).sqrt() / 2.0);
    // p = (-u, v) on d1 with v = (u - 1) tan θ: solve u² + (v - h1)² = r1².
    let tan = st / ct;
    let (qa, qb, qc) = (
        1.0 + tan * tan,
        -2.0 * tan * tan - 2.0 * tan * h1,
        tan * tan + 2.0 * tan * h1 + h1 * h1 - r1 * r1,
    );
    let u = (-qb + (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa);
    let v = (u - 1.0) * tan;
    let (p, r) = ([-u, v], [u, v]);
    let q = [-u + 2.0 * u * ct, v - 2.0 * u * st];
    let s = [-q[0], q[1]];
    let bf = beta.to_f64();
    let (r2, h2) = (bf, (bf * bf - 1.0).sqrt());
    let lower2 = [0.0, -h2];
    let s_prime = outside(
        ray_circle(y, s, lower2, r2),
        [s[0] - y[0], s[1] - y[1]],
        &x,
        &y,
        beta,
    );
    let q_prime = [-s_prime[0], s_prime[1]];
    // δ of the thesis, also below the distance from r to the β-circle above xy.
    let pr = dist(p, r);
    let gap_circle = dist(r, [0.0, h2]) - r2;
    let delta = 0.5
        * [
            dist(s, s_prime),
            pr - dist(p, y),
            pr + dist(p, y) - 2.0 * dist(p, q_prime),
            2.0 * gap_circle,
        ]
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    if delta.is_nan() || delta <= 1e-9 {
        return Err(PlanarError::new(format!(
            "β = {beta} is so close to the upper end that δ = {delta:.3e} is below double precision's reach"
        )));
    }
    let alpha = pr + dist(p, y) - 2.0 * dist(p, q_prime);
    let (p1r1, xs) = (pr, dist(x, s_prime));
    let lemma_bound = 2.0 / (2.0 * alpha - 3.0 * delta) * (p1r1 - 2.0 + dist(p, s_prime) - xs);
    let build = move |n: usize| -> Vec<Point2> {
        // The arc near r, in coordinates along the line y → r (ℓ from y, unit e) and the
        // offset d to its left (towards the band above xy), u = distance down from the
        // top site. Lemma 5.5(i) (the fans from s' and from y do not cross) needs the
        // slope dd/dℓ between d/(ℓ + |ys'|) and d/ℓ; the chain edges must be forced, so
        // the arc bulges towards the band (d concave in ℓ): the slope runs from just
        // above the lower limit at the top to just below the upper one at the bottom.
        let lr = dist(y, r);
        let e = [(r[0] - y[0]) / lr, (r[1] - y[1]) / lr];
        let left = [-e[1], e[0]];
        let ys = dist(y, s_prime);
        let (d0, span) = (0.15 * delta, 0.3 * delta);
        let (g_top, g_bottom) = (1.2 * d0 / (lr + ys), 0.8 * d0 / lr);
        let kappa = (g_bottom - g_top) / span;
        let arc: Vec<Point2> = (0..n)
            .map(|i| {
                let t = if n == 1 {
                    0.0
                } else {
                    i as f64 / (n - 1) as f64
                };
                let u = t * span;
                let l = lr - 0.02 * delta - u;
                let d = d0 - g_top * u - 0.5 * kappa * u * u;
                [y[0] + l * e[0] + d * left[0], y[1] + l * e[1] + d * left[1]]
            })
            .collect();
        let mut sites = vec![q_prime, x];
        sites.extend(arc.iter().rev().map(|a| [-a[0], a[1]]));
        sites.extend(arc.iter().copied());
        sites.push(y);
        sites.push(s_prime);
        sites
    };
    Ok((Box::new(build), lemma_bound))
}

/// True when β exceeds the Cheng–Xu bound `√(2√3+9)/3 ≈ 1.17682`, above which the
/// β-skeleton is a subgraph of every MWT: `t = 9β² − 9 > 0` and `t² > 12` (exact).
pub fn above_cheng_xu(beta: Ratio) -> bool {
    let (a, b) = (beta.num as i128, beta.den as i128);
    let t = 9 * a * a - 9 * b * b; // t_true = t / b²
    t > 0
        && match (
            t.checked_mul(t),
            (b * b).checked_mul(b * b).and_then(|x| x.checked_mul(12)),
        ) {
            (Some(l), Some(r)) => l > r,
            _ => {
                let tf = t as f64 / (b * b) as f64;
                tf * tf > 12.0 * (1.0 + 1e-12)
            }
        }
}

/// A violation of β-skeleton ⊆ MWT: `(set, seed, edge)`.
pub type Violation = (usize, u64, [u32; 2]);

/// Checks β-skeleton ⊆ MWT on `sets` random uniform point sets of `n` points: returns
/// the number of skeleton edges checked and every violation `(set, seed, edge)`.
pub fn check_random(
    beta: Ratio,
    sets: usize,
    n: usize,
    seed: u64,
) -> Result<(usize, Vec<Violation>), PlanarError> {
    let mut checked = 0;
    let mut bad = Vec::new();
    for k in 0..sets {
        let s = seed.wrapping_add(k as u64);
        let pts = super::points2d(super::Distribution::Uniform, n, s);
        let sk = super::beta_skeleton(&pts, beta, super::Region::Circle)?;
        let m = mwt(&pts)?;
        for e in sk.edges {
            checked += 1;
            if m.edges.binary_search(&e).is_err() {
                bad.push((k, s, e));
            }
        }
    }
    Ok((checked, bad))
}
