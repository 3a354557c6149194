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
//! The floating-point construction (module `construction`) is only a proposal: the
//! verdicts are computed on the actual sites, by the exact skeleton test and by the
//! best triangulations with and without `xy`, found by splitting along the polygon `L`
//! of Lemma 5.6 (module `split`, every side certified) or else by the general MWT
//! solver, and compared exactly. What is reported is proven for these sites.

mod construction;
mod split;

use super::{MwtOptions, PlanarError, cmp_edge_sets, mwt, weight_of};
use crate::control::Control;
use crate::geom::{Interval, Point2, Ratio, in_beta_region};
use construction::construction;
use num_bigint::{BigInt, Sign};
use rayon::prelude::*;
use split::Optima;
use std::cmp::Ordering;

/// True when β lies in `[2/√3, √(2√3+45)/6)`, where the construction applies (exact):
/// `β ≥ 2/√3 ⟺ 3β² ≥ 4`, and `β < √(2√3+45)/6 ⟺ 36β² − 45 < √12`.
pub fn in_keil_interval(beta: Ratio) -> bool {
    beta.square_cmp(4, 3) != Ordering::Less && cmp_with_root12(beta, 36, 45) == Ordering::Less
}

/// The exact comparison of `c·β² − d` with `√12 = 2√3`, in integers: with `β = a/b`
/// and `t = c·a² − d·b²`, it is `t` against `√12·b²`, so `Less` when `t ≤ 0`, else the
/// comparison of `t²` with `12·b⁴`.
fn cmp_with_root12(beta: Ratio, c: u32, d: u32) -> Ordering {
    let (a, b) = (BigInt::from(beta.num), BigInt::from(beta.den));
    let t = BigInt::from(c) * &a * &a - BigInt::from(d) * &b * &b;
    if t.sign() != Sign::Plus {
        return Ordering::Less;
    }
    let b2 = &b * &b;
    (&t * &t).cmp(&(BigInt::from(12) * &b2 * &b2))
}

/// Largest site count for the constrained optima, which use all `O(n²)` segments.
pub const CONSTRAINED_LIMIT: usize = 160;

/// Keil's construction for one β: the sites, `xy`, and the exact skeleton test on it
/// (what [`keil`] knows before any triangulation is optimized).
#[derive(Clone, Debug)]
pub struct KeilConstruction {
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
}

/// The Keil point set and what was found on it.
#[derive(Clone, Debug)]
pub struct KeilResult {
    /// The construction and the skeleton test.
    pub construction: KeilConstruction,
    /// `xy` is an edge of some minimum weight triangulation (exact).
    pub xy_in_mwt: bool,
    /// A minimum weight triangulation (the one with `xy` on a tie).
    pub mwt: Vec<[u32; 2]>,
    /// Weight of the best triangulation containing `xy`, and its edges.
    pub with_xy: (Interval, Vec<[u32; 2]>),
    /// Weight of the best triangulation without `xy`, and its edges.
    pub without_xy: (Interval, Vec<[u32; 2]>),
    /// Exact comparison of the two: `Greater` when containing `xy` costs more.
    pub with_vs_without: Ordering,
    /// The optima were found by splitting along `L` (thesis Lemma 5.6, every side of
    /// `L` certified uncrossable) rather than by the general MWT solver.
    pub split: bool,
}

/// The answer of [`keil`]: everything decided, or what was known when stopped.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum KeilOutcome {
    /// Both questions on `xy` decided exactly.
    Decided(KeilResult),
    /// Stopped before the optima were found: the construction alone.
    Undecided(KeilConstruction),
}

impl KeilOutcome {
    /// The construction, decided or not.
    pub fn construction(&self) -> &KeilConstruction {
        match self {
            KeilOutcome::Decided(k) => &k.construction,
            KeilOutcome::Undecided(c) => c,
        }
    }

    /// The decided result, if it is one.
    pub fn decided(self) -> Option<KeilResult> {
        match self {
            KeilOutcome::Decided(k) => Some(k),
            KeilOutcome::Undecided(_) => None,
        }
    }
}

/// The best triangulation containing `xy`, for `x`, `y` on the hull and no other site on
/// the line `xy`: the chord splits the hull into two convex regions whose triangulations
/// are those of the sites on each side plus `x` and `y`, so it is the union of two
/// unconstrained MWTs (the diamond test applies to each). Otherwise the constrained
/// solver over all segments.
fn best_with_chord(
    sites: &[Point2],
    xy: [u32; 2],
    ctl: &Control,
) -> Result<super::Mwt, PlanarError> {
    let (x, y) = (&sites[xy[0] as usize], &sites[xy[1] as usize]);
    let hull = crate::geom::Hull2::new(sites);
    let side: Vec<i8> = sites
        .iter()
        .map(|p| crate::geom::orient2d(x, y, p))
        .collect();
    let on_line = (0..sites.len()).any(|i| side[i] == 0 && i as u32 != xy[0] && i as u32 != xy[1]);
    let on_hull = hull.vertices.contains(&xy[0]) && hull.vertices.contains(&xy[1]);
    if on_line || !on_hull {
        let forced = MwtOptions {
            forced: vec![xy],
            ..Default::default()
        };
        return mwt(sites, &forced, ctl);
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
        for e in mwt(&pts, &MwtOptions::default(), ctl)?.edges {
            let (a, b) = (ids[e[0] as usize], ids[e[1] as usize]);
            edges.push(super::edge_key(a, b));
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

/// Largest `n` accepted (the polygon dynamic program on `2n + 4` sites keeps
/// `(2n + 4)²/2` cells of 24 bytes).
pub const MAX_N: usize = 4000;

/// Builds the construction for `beta` with `n` sites per arc (`None`: one more than
/// Lemma 5.8's bound, where the thesis proves `xy` is in no MWT) and decides everything
/// exactly: the skeleton test on `xy`, and the best triangulations with and without
/// `xy`, compared exactly.
///
/// The optima are found by splitting along the polygon `L` when every side of `L` is
/// certified to be in every triangulation (`split`), else by the general MWT solver.
/// Stopped by `ctl` first, the answer is [`KeilOutcome::Undecided`] with the
/// construction and the skeleton test.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::{KeilOutcome, keil};
/// let k = keil("1.1548".parse().unwrap(), Some(20), &Control::new()).unwrap();
/// let k = k.decided().unwrap();
/// assert!(k.construction.xy_in_skeleton && !k.xy_in_mwt);
/// assert!(k.with_xy.0.lo > k.without_xy.0.hi);
/// let stopped = Control::new();
/// stopped.stop();
/// let k = keil("1.1548".parse().unwrap(), Some(20), &stopped).unwrap();
/// assert!(matches!(k, KeilOutcome::Undecided(s) if s.xy_in_skeleton));
/// ```
pub fn keil(beta: Ratio, n: Option<usize>, ctl: &Control) -> Result<KeilOutcome, PlanarError> {
    let (build, lemma_bound) = construction(beta)?;
    let n = n
        .unwrap_or((lemma_bound.max(0.0).floor() as usize).saturating_add(1))
        .max(1);
    if n > MAX_N {
        return Err(PlanarError::KeilTooLarge {
            n,
            limit: MAX_N,
            lemma_bound,
        });
    }
    let sites = build(n);
    let (x, y) = (sites[1], sites[2 * n + 2]);
    let xy = [1u32, (2 * n + 2) as u32];
    let xy_in_skeleton = (0..sites.len()).all(|i| {
        i as u32 == xy[0] || i as u32 == xy[1] || !in_beta_region(&x, &y, &sites[i], beta)
    });
    let cycle: Vec<u32> = (0..sites.len() as u32).collect();
    let found = split::split_along(&sites, &cycle, xy, ctl).and_then(|s| match s {
        Some(s) => Ok((s, true)),
        None => Ok((general(&sites, xy, ctl)?, false)),
    });
    let construction = KeilConstruction {
        beta,
        sites,
        xy,
        n,
        lemma_bound,
        xy_in_skeleton,
    };
    let (optima, split) = match found {
        Err(PlanarError::Stopped(_)) => return Ok(KeilOutcome::Undecided(construction)),
        other => other?,
    };
    let sites = &construction.sites;
    let Optima {
        with_xy: with,
        without_xy: without,
    } = optima;
    let with_vs_without = cmp_edge_sets(sites, &with, &without);
    let xy_in_mwt = with_vs_without != Ordering::Greater;
    Ok(KeilOutcome::Decided(KeilResult {
        xy_in_mwt,
        mwt: if xy_in_mwt {
            with.clone()
        } else {
            without.clone()
        },
        with_xy: (weight_of(sites, &with), with),
        without_xy: (weight_of(sites, &without), without),
        with_vs_without,
        split,
        construction,
    }))
}

/// The two optima by the general solver: the MWT, the best triangulation with `xy`,
/// and, when the MWT contains `xy`, the best one without it (over all segments).
fn general(sites: &[Point2], xy: [u32; 2], ctl: &Control) -> Result<Optima, PlanarError> {
    let best = mwt(sites, &MwtOptions::default(), ctl)?;
    let with = best_with_chord(sites, xy, ctl)?.edges;
    if best.edges.binary_search(&xy).is_err() {
        return Ok(Optima {
            with_xy: with,
            without_xy: best.edges,
        });
    }
    if sites.len() > CONSTRAINED_LIMIT {
        return Err(PlanarError::KeilConstrainedTooLarge {
            sites: sites.len(),
            limit: CONSTRAINED_LIMIT,
        });
    }
    let opts = MwtOptions {
        forbidden: vec![xy],
        ..Default::default()
    };
    Ok(Optima {
        with_xy: with,
        without_xy: mwt(sites, &opts, ctl)?.edges,
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

/// True when β exceeds the Cheng–Xu bound `√(2√3+9)/3 ≈ 1.17682`, above which the
/// β-skeleton is a subgraph of every MWT: `9β² − 9 > √12` (exact).
pub fn above_cheng_xu(beta: Ratio) -> bool {
    cmp_with_root12(beta, 9, 9) == Ordering::Greater
}

/// A violation of β-skeleton ⊆ MWT: `(set, seed, edge)`.
pub type Violation = (usize, u64, [u32; 2]);

/// Checks β-skeleton ⊆ MWT on `sets` random uniform point sets of `n` points: returns
/// the number of skeleton edges checked and every violation `(set, seed, edge)`, in set
/// order. The sets are checked in parallel (in the pool, where the solver's own parallel
/// loops are cheap), each reported as done to `ctl`.
pub fn check_random(
    beta: Ratio,
    sets: usize,
    n: usize,
    seed: u64,
    ctl: &Control,
) -> Result<(usize, Vec<Violation>), PlanarError> {
    let done = std::sync::atomic::AtomicU64::new(0);
    let quiet = Control::new();
    let one = |k: usize| -> Result<(usize, Vec<Violation>), PlanarError> {
        ctl.check()?;
        let s = seed.wrapping_add(k as u64);
        let pts = super::points2d(super::Distribution::Uniform, n, s);
        let sk = super::beta_skeleton(&pts, beta, super::Region::Circle, &quiet)?;
        let m = mwt(&pts, &MwtOptions::default(), &quiet)?;
        let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        ctl.items(d, sets as u64);
        let checked = sk.edges.len();
        let bad = (sk.edges.into_iter())
            .filter(|e| m.edges.binary_search(e).is_err())
            .map(|e| (k, s, e))
            .collect();
        Ok((checked, bad))
    };
    let results: Vec<_> = (0..sets).into_par_iter().map(one).collect();
    let mut total = (0, Vec::new());
    for r in results {
        let (checked, bad) = r?;
        total.0 += checked;
        total.1.extend(bad);
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sets are checked in parallel; the count and the violations, in set order, are
    /// those of checking each set alone. At β = 1 (the Gabriel graph, far below the
    /// Cheng–Xu bound) random sets have skeleton edges outside their MWT.
    #[test]
    fn parallel_check_matches_one_set_at_a_time() {
        let beta: Ratio = "1".parse().unwrap();
        let (checked, bad) = check_random(beta, 6, 40, 7, &Control::new()).unwrap();
        let mut alone = (0, Vec::new());
        for k in 0..6 {
            let (c, b) = check_random(beta, 1, 40, 7 + k as u64, &Control::new()).unwrap();
            alone.0 += c;
            alone.1.extend(b.into_iter().map(|(_, s, e)| (k, s, e)));
        }
        assert!(!bad.is_empty());
        assert_eq!((checked, bad), alone);
    }

    /// 15-digit decimals on both sides of each bound (their squares overflow 128-bit
    /// arithmetic in the comparison with √12, so this pins the exact path).
    #[test]
    fn interval_ends_are_exact() {
        let b = |s: &str| s.parse::<Ratio>().unwrap();
        assert!(!in_keil_interval(b("1.15470053837925")));
        assert!(in_keil_interval(b("1.15470053837926")));
        assert!(in_keil_interval(b("1.16026938461071")));
        assert!(!in_keil_interval(b("1.16026938461072")));
        assert!(!above_cheng_xu(b("1.17681781914608")));
        assert!(above_cheng_xu(b("1.17681781914609")));
    }
}
