//! Instances for [`super::constrained`]: niches (thesis §2.6) among other points.

use super::niche::{Niche, find_niches};
use crate::geom::Point3;
use crate::params::GenerateError;
use crate::rng::Rng;

/// A generated CT instance and the niche it was built around.
#[derive(Clone, Debug, PartialEq)]
pub struct NicheInstance {
    /// The points: Schönhardt's six, then the others.
    pub points: Vec<Point3>,
    /// Schönhardt's twelve edges.
    pub constraints: Vec<[u32; 2]>,
    /// Its bottom niche.
    pub niche: Niche,
}

/// A CT instance: Schönhardt's polyhedron (the prism twisted by `twist` degrees, in
/// (0°, 120°)) with its twelve edges as constraints, and `extra` random points around it
/// outside the view of its bottom niche; with `in_view`, one more point at the prism's
/// centre, which sees both niches' bases (refused if it does not).
///
/// ```
/// use tetrakit::constrain::{Answer, Options, WitnessKind, constrained, generate::niche};
/// use tetrakit::control::Control;
/// let g = niche(30.0, 6, false, 1).unwrap();
/// assert!(g.niche.vertex_in_view(&g.points).is_none());
/// let d = constrained(&g.points, &g.constraints, &Options::default(), &Control::new()).unwrap();
/// let Answer::No(w) = d.answer else { panic!() };
/// assert_eq!(w.kind, WitnessKind::EmptyNicheView);
/// ```
pub fn niche(
    twist: f64,
    extra: usize,
    in_view: bool,
    seed: u64,
) -> Result<NicheInstance, GenerateError> {
    if !(twist > 0.0 && twist < 120.0) {
        return Err(GenerateError::range(
            "twist",
            twist,
            "in (0°, 120°) for a niche",
        ));
    }
    if extra > 10_000 {
        return Err(GenerateError::range("extra", extra, "at most 10000"));
    }
    let s = crate::polyhedra::generate::twisted_prism(twist)?;
    let segs = s.edges();
    let n = *find_niches(&s.points, &segs)
        .iter()
        .find(|n| n.base.iter().all(|&v| v < 3))
        .ok_or(GenerateError::Unbuildable(
            "the twisted prism has no niche at its bottom",
        ))?;
    let mut pts = s.points.clone();
    let mut rng = Rng::new(seed);
    while pts.len() < 6 + extra {
        let p = [
            8.0 * rng.unit() - 4.0,
            8.0 * rng.unit() - 4.0,
            6.0 * rng.unit() - 2.0,
        ];
        let near = p[0].abs() < 1.5 && p[1].abs() < 1.5 && (-0.5..2.5).contains(&p[2]);
        pts.push(p);
        let k = pts.len() as u32 - 1;
        if near || n.sees_base(&pts, k) {
            pts.pop();
        }
    }
    if in_view {
        pts.push([0.0, 0.0, 1.0]);
        let centre = pts.len() as u32 - 1;
        if find_niches(&pts, &segs)
            .iter()
            .any(|m| !m.sees_base(&pts, centre))
        {
            return Err(GenerateError::Unbuildable(
                "at this twist the centre does not see both niches' bases",
            ));
        }
    }
    Ok(NicheInstance {
        points: pts,
        constraints: segs,
        niche: n,
    })
}

/// A grid of Schönhardt gadgets for [`super::constrained`]: `rows × cols` towers of
/// `layers` prisms ([`schonhardt_tower`](crate::polyhedra::hard::schonhardt_tower), each
/// layer twisted by `twist` degrees, in (0°, 60°)), their axes `spacing` apart (at least
/// 2.5, so that the towers are disjoint), with all their edges as constraints. No other
/// point: each gadget's niches must find a vertex of another one in their view, which
/// looks along the axis: a chain (one tower) sees its neighbours, a flat grid does not.
///
/// ```
/// use tetrakit::constrain::generate::gadget_grid;
/// let (points, constraints) = gadget_grid(2, 3, 1, 30.0, 3.0).unwrap();
/// assert_eq!((points.len(), constraints.len()), (36, 72));
/// ```
pub fn gadget_grid(
    rows: usize,
    cols: usize,
    layers: usize,
    twist: f64,
    spacing: f64,
) -> Result<(Vec<Point3>, Vec<[u32; 2]>), GenerateError> {
    let gadgets = rows.saturating_mul(cols).saturating_mul(layers);
    if !(1..=100_000).contains(&gadgets) {
        let value = format!("{rows} × {cols} × {layers}");
        let expected = "between 1 and 100000 gadgets";
        return Err(GenerateError::range(
            "rows × cols × layers",
            value,
            expected,
        ));
    }
    if !(twist > 0.0 && twist < 60.0) {
        return Err(GenerateError::range("twist", twist, "in (0°, 60°)"));
    }
    if spacing.is_nan() || spacing < 2.5 {
        return Err(GenerateError::range("spacing", spacing, "at least 2.5"));
    }
    let s = crate::polyhedra::hard::schonhardt_tower(layers, twist)?;
    let edges = s.edges();
    let (mut points, mut constraints) = (Vec::new(), Vec::new());
    for r in 0..rows {
        for c in 0..cols {
            let base = points.len() as u32;
            let (dx, dy) = (spacing * c as f64, spacing * r as f64);
            points.extend(s.points.iter().map(|p| [p[0] + dx, p[1] + dy, p[2]]));
            constraints.extend(edges.iter().map(|&[a, b]| [a + base, b + base]));
        }
    }
    Ok((points, constraints))
}
