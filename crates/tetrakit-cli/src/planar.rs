//! Chapter 5 commands: `skeleton`, `mwt`, `keil`, and `generate points2d`.

use crate::run::fail;
use serde_json::json;
use std::path::Path;
use std::time::Instant;
use tetrakit::geom::{Point2, Ratio};
use tetrakit::io;
use tetrakit::planar::{self, Distribution, Region};

/// Reads planar points (z must be 0 in 3D formats).
pub fn read_points(path: &Path) -> Result<Vec<Point2>, u8> {
    let input = io::read_input(path).map_err(fail)?;
    if let Some(i) = input.points.iter().position(|p| p[2] != 0.0) {
        let line = input.point_lines.get(i).copied().unwrap_or(0);
        return Err(fail(format!(
            "{}:{line}: point {} has z = {}; planar commands need 2D points",
            path.display(),
            i as u32 + input.index_base,
            input.points[i][2]
        )));
    }
    Ok(input.points.iter().map(|p| [p[0], p[1]]).collect())
}

pub fn parse_beta(text: &str) -> Result<Ratio, u8> {
    text.parse::<Ratio>()
        .map_err(|e| fail(format!("--beta: {e}")))
}

pub fn skeleton(path: &Path, beta: &str, lune: bool, as_json: bool, output: Option<&Path>) -> u8 {
    let start = Instant::now();
    let beta = match parse_beta(beta) {
        Ok(b) => b,
        Err(c) => return c,
    };
    let points = match read_points(path) {
        Ok(p) => p,
        Err(c) => return c,
    };
    let parsed = start.elapsed().as_secs_f64();
    let region = if lune { Region::Lune } else { Region::Circle };
    let t = Instant::now();
    let sk = match planar::beta_skeleton(&points, beta, region) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output
        && let Err(e) = io::write_planar_edges(out, &points, &sk.edges)
    {
        return fail(format!("{}: {e}", out.display()));
    }
    let region_name = if lune { "lune" } else { "circle" };
    if as_json {
        out!(
            "{}",
            json!({
                "beta": beta.to_string(),
                "region": region_name,
                "vertices": points.len(),
                "edges": sk.edges.len(),
                "candidates": sk.candidates,
                "cell_diameters": sk.cell_diameters,
                "seconds": start.elapsed().as_secs_f64(),
                "seconds_parse": parsed,
                "seconds_algorithm": algorithm,
            })
        );
    } else {
        out!(
            "{region_name}-based β-skeleton, β = {beta}: {} edges on {} sites ({} candidates tested exactly) in {:.3} s",
            sk.edges.len(),
            points.len(),
            sk.candidates,
            algorithm
        );
    }
    0
}

pub fn mwt(path: &Path, as_json: bool, output: Option<&Path>) -> u8 {
    let start = Instant::now();
    let points = match read_points(path) {
        Ok(p) => p,
        Err(c) => return c,
    };
    let parsed = start.elapsed().as_secs_f64();
    let t = Instant::now();
    let m = match planar::mwt(&points) {
        Ok(m) => m,
        Err(e) => return fail(e),
    };
    let algorithm = t.elapsed().as_secs_f64();
    if let Some(out) = output
        && let Err(e) = io::write_planar_edges(out, &points, &m.edges)
    {
        return fail(format!("{}: {e}", out.display()));
    }
    let s = &m.stats;
    if as_json {
        out!(
            "{}",
            json!({
                "vertices": points.len(),
                "edges": m.edges.len(),
                "triangles": m.triangles.len(),
                "weight": m.weight.mid(),
                "weight_interval": [m.weight.lo, m.weight.hi],
                "candidates": s.candidates,
                "skeleton_edges": s.skeleton_edges,
                "undecided_edges": s.undecided_edges,
                "faces_left": s.faces_left,
                "faces_with_holes": s.faces_with_holes,
                "largest_face": s.largest_face,
                "seconds": start.elapsed().as_secs_f64(),
                "seconds_parse": parsed,
                "seconds_stages": { "diamond": s.seconds[0], "lmt": s.seconds[1], "exact": s.seconds[2] },
                "seconds_algorithm": algorithm,
            })
        );
    } else {
        let fixed = 100.0 * s.skeleton_edges as f64 / m.edges.len().max(1) as f64;
        out!(
            "minimum weight triangulation of {} sites: {} edges, {} triangles, weight {:.12} (certified in [{:.17e}, {:.17e}])",
            points.len(),
            m.edges.len(),
            m.triangles.len(),
            m.weight.mid(),
            m.weight.lo,
            m.weight.hi
        );
        out!(
            "  {} candidates after the diamond test; LMT-skeleton fixed {} edges ({fixed:.1}%); {} faces left to the exact stage ({} with holes, largest {}); {:.3} s",
            s.candidates,
            s.skeleton_edges,
            s.faces_left,
            s.faces_with_holes,
            s.largest_face,
            algorithm
        );
    }
    0
}

pub fn generate_points(dist: Distribution, n: usize, seed: u64, output: &Path) -> u8 {
    if !(1..=50_000_000).contains(&n) {
        return fail("--n must be between 1 and 50000000");
    }
    let pts = planar::points2d(dist, n, seed);
    if let Err(e) = io::write_points2d(output, &pts) {
        return fail(format!("{}: {e}", output.display()));
    }
    out!(
        "wrote {} {dist:?} points to {}",
        pts.len(),
        output.display()
    );
    0
}
