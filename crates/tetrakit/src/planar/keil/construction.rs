//! The point set of thesis §5.2 (Figure 5.3) in floating point: `x`, `y`, Cheng and
//! Xu's `p, q, r, s` (Lemma 5.3), `q'`, `s'` on the β-circle, and the two arcs of `n`
//! sites near `p` and `r`, with `δ` of Lemma 5.4 and the bound of Lemma 5.8.
//!
//! The construction is only a proposal: every verdict is computed on the actual sites
//! by exact tests, so what is reported is proven for these sites.

use super::in_keil_interval;
use crate::geom::{Point2, Ratio, in_beta_region};
use crate::planar::PlanarError;

/// Builds the sites for a given `n`.
pub(super) type Builder = Box<dyn Fn(usize) -> Vec<Point2> + Sync>;

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

/// The site builder (sites for a given `n`) and Lemma 5.8's bound on `n`.
pub(super) fn construction(beta: Ratio) -> Result<(Builder, f64), PlanarError> {
    if !in_keil_interval(beta) {
        return Err(PlanarError::BetaOutsideKeilInterval { beta });
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
        return Err(PlanarError::BetaTooCloseToUpperEnd { beta, delta });
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
