//! The picture of the Keil construction (thesis §5.2): a drawing of a result, so it sits
//! with the printers of results, on `io`'s SVG writer.

use crate::geom::Point2;
use crate::io::{Figure, Svg};
use crate::planar::KeilResult;

/// The picture of the Keil construction (thesis §5.2), as SVG text, in three panels:
/// (a) the whole construction: the sites, the two β-disks through `x` and `y`, the MWT
/// (blue), `xy` (dashed red) and boxes marking the other two panels; (b) the
/// neighbourhood of `x`, magnified so that the MWT's fan from `q'` to the sites `p_i` is
/// seen to cross `xy` just beside `x`; (c) the sites `p_i`, magnified, with the edges of
/// the best triangulation containing `xy` that the MWT lacks (dashed orange): with `xy`
/// the `p_i` are joined across to the `r_i` instead of to `q'`. The caption gives both
/// weights and the exact verdicts.
///
pub fn keil_svg(k: &KeilResult) -> String {
    let x = k.construction.sites[k.construction.xy[0] as usize];
    let b = k.construction.beta.to_f64();
    let h = (b * b - 1.0).sqrt();
    let mut view = k.construction.sites.clone();
    view.extend([[-b, h + b], [b, -h - b]]);
    let (lo, hi) = crate::geom::bounding_box(&view);
    let m = 0.06 * (hi[0] - lo[0]);
    let whole = ([lo[0] - m, lo[1] - m], [hi[0] + m, hi[1] + m]);
    let zoom_w = 430.0;
    let (w_a, h_b) = (430.0, 300.0);
    let arc = &k.construction.sites[2..2 + k.construction.n];
    let near_x = around(&x, 3.0 * fan_offset(k), zoom_w / h_b);
    let (alo, ahi) = crate::geom::bounding_box(arc);
    let c = [(alo[0] + ahi[0]) / 2.0, (alo[1] + ahi[1]) / 2.0];
    let half = (ahi[0] - alo[0]).max((ahi[1] - alo[1]) * zoom_w / h_b) * 0.6;
    let near_arc = around(&c, half.max(1e-12), zoom_w / h_b);
    let mut panels = Vec::new();
    for (i, (wlo, whi)) in [whole, near_x, near_arc].into_iter().enumerate() {
        let mut svg = Svg::window(wlo, whi, if i == 0 { w_a } else { zoom_w });
        draw_keil(&mut svg, k, [h, b], i > 0);
        if i == 0 {
            svg.rect(&near_x.0, &near_x.1, "zoom");
            svg.rect(&near_arc.0, &near_arc.1, "zoom");
        }
        panels.push(svg);
    }
    let mag = |s: &Svg| s.scale() / panels[0].scale();
    let titles = [
        "(a) the construction".to_string(),
        format!("(b) around x, ×{:.0}", mag(&panels[1])),
        format!("(c) the sites p_i, ×{:.0}", mag(&panels[2])),
    ];
    let height = 30.0 + panels[0].size().1.max(2.0 * h_b + 40.0);
    let mut f = Figure::new(w_a + zoom_w + 30.0, height);
    let at = [(10.0, 30.0), (w_a + 20.0, 30.0), (w_a + 20.0, 70.0 + h_b)];
    for ((svg, at), title) in panels.into_iter().zip(at).zip(&titles) {
        f.panel(svg, at, title);
    }
    f.finish(&keil_caption(k))
}

/// The caption of the Keil picture: the verdicts, what the panels show, the weights.
fn keil_caption(k: &KeilResult) -> String {
    let (with, without) = (k.with_xy.0.mid(), k.without_xy.0.mid());
    let why = if k.xy_in_mwt {
        format!(
            "With n = {} sites per arc xy is in an MWT: the construction needs more (Lemma 5.8: n > {:.1}).",
            k.construction.n, k.construction.lemma_bound
        )
    } else {
        "The MWT's fans from q' to the p_i and from s' to the r_i cross xy beside x and y (b);\n\
         keeping xy, the p_i are joined across to the r_i instead (dashed orange, (c))."
            .to_string()
    };
    let cost = match k.with_vs_without {
        std::cmp::Ordering::Greater => format!("xy costs {:.6} more", with - without),
        std::cmp::Ordering::Equal => "a tie".to_string(),
        std::cmp::Ordering::Less => format!("xy saves {:.6}", without - with),
    };
    format!(
        "β = {}: xy (dashed red) is {} the β-skeleton (the disks: its β-region) and {} the MWT (blue).\n\
         {why}\nWeight with xy {with:.6}, without {without:.6}: {cost} (compared exactly).",
        k.construction.beta,
        if k.construction.xy_in_skeleton {
            "in"
        } else {
            "not in"
        },
        if k.xy_in_mwt { "in" } else { "not in" },
    )
}

/// The marks of the Keil picture, the same in every panel (each clips them); the ends of
/// the arc of `p_i` are named where it is magnified (`detail`).
fn draw_keil(svg: &mut Svg, k: &KeilResult, [h, b]: [f64; 2], detail: bool) {
    let (x, y) = (
        k.construction.sites[k.construction.xy[0] as usize],
        k.construction.sites[k.construction.xy[1] as usize],
    );
    for c in [[0.0, h], [0.0, -h]] {
        svg.circle(&c, b, "disk");
    }
    let mwt: std::collections::HashSet<&[u32; 2]> = k.mwt.iter().collect();
    for e in k.with_xy.1.iter().filter(|e| !mwt.contains(e)) {
        svg.line(
            &k.construction.sites[e[0] as usize],
            &k.construction.sites[e[1] as usize],
            "best",
        );
    }
    for e in &k.mwt {
        svg.line(
            &k.construction.sites[e[0] as usize],
            &k.construction.sites[e[1] as usize],
            "mwt",
        );
    }
    svg.line(&x, &y, "xy");
    for p in &k.construction.sites {
        svg.site(p);
    }
    svg.label(&x, "x");
    svg.label(&y, "y");
    svg.label(&k.construction.sites[0], "q'");
    if detail {
        svg.label(&k.construction.sites[2], "p_n");
        svg.label(&k.construction.sites[k.construction.n + 1], "p_1");
    }
}

/// How far from `x` the MWT edges crossing `xy` meet it (at least a tiny positive length,
/// so the window around `x` is never empty).
fn fan_offset(k: &KeilResult) -> f64 {
    let (x, y) = (
        k.construction.sites[k.construction.xy[0] as usize],
        k.construction.sites[k.construction.xy[1] as usize],
    );
    let len = ((y[0] - x[0]).powi(2) + (y[1] - x[1]).powi(2)).sqrt();
    let mut far: f64 = 1e-9 * len;
    for e in &k.mwt {
        let (p, q) = (
            k.construction.sites[e[0] as usize],
            k.construction.sites[e[1] as usize],
        );
        let (sp, sq) = (side(&x, &y, &p), side(&x, &y, &q));
        if sp * sq < 0.0 {
            let t = sp / (sp - sq);
            let at = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            let d = ((at[0] - x[0]).powi(2) + (at[1] - x[1]).powi(2)).sqrt();
            if d < 0.25 * len {
                far = far.max(d);
            }
        }
    }
    far
}

fn side(a: &Point2, b: &Point2, p: &Point2) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// The window of half-width `half` centred at `c`, `aspect` times wider than tall.
fn around(c: &Point2, half: f64, aspect: f64) -> (Point2, Point2) {
    let hh = half / aspect;
    ([c[0] - half, c[1] - hh], [c[0] + half, c[1] + hh])
}
