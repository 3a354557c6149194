//! Instances for [`super::constrained`]: niches (thesis §2.6) among other points.

use super::niche::{Niche, find_niches};
use crate::geom::Point3;
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
pub fn niche(twist: f64, extra: usize, in_view: bool, seed: u64) -> Result<NicheInstance, String> {
    if !(twist > 0.0 && twist < 120.0) {
        return Err(format!(
            "a twist of {twist}°: a niche needs a twist in (0°, 120°)"
        ));
    }
    if extra > 10_000 {
        return Err(format!("{extra} extra points: at most 10000"));
    }
    let s = crate::polyhedra::generate::twisted_prism(twist)
        .map_err(|e| format!("a twist of {twist}°: the prism is not a simple polyhedron ({e})"))?;
    let segs = s.edges();
    let n = *find_niches(&s.points, &segs)
        .iter()
        .find(|n| n.base.iter().all(|&v| v < 3))
        .ok_or("the twisted prism has no niche at its bottom")?;
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
            return Err(format!(
                "at a twist of {twist}° the centre does not see both niches' bases"
            ));
        }
    }
    Ok(NicheInstance {
        points: pts,
        constraints: segs,
        niche: n,
    })
}
