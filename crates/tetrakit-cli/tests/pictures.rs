//! Every SVG the tool writes is rendered by a real renderer (`rsvg-convert`, Debian's
//! `librsvg2-bin`; `.ci/run` installs it and sets `TETRAKIT_REQUIRE_RSVG`) and the
//! picture is checked to show what its caption names: the colours of the marks the
//! caption lists are found, by pixel, in the panels that are said to show them.

mod common;

use std::path::Path;
use std::process::Command;

/// Runs the binary, which must succeed, and returns its stdout.
fn run(args: &[&str]) -> Vec<u8> {
    let o = Command::new(env!("CARGO_BIN_EXE_tetrakit"))
        .args(args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    o.stdout
}

/// Runs a command with `--json` among `args` and parses its answer.
fn tetrakit(args: &[&str]) -> serde_json::Value {
    serde_json::from_slice(&run(args)).unwrap()
}

/// An RGB raster.
struct Image {
    width: usize,
    pixels: Vec<[u8; 3]>,
}

/// Renders `svg` to PNG at its own size and decodes it; `None` when `rsvg-convert` is
/// missing and not required.
fn render(svg: &Path) -> Option<Image> {
    let png = svg.with_extension("png");
    let Ok(o) = Command::new("rsvg-convert")
        .arg(svg)
        .arg("-o")
        .arg(&png)
        .output()
    else {
        assert!(
            std::env::var_os("TETRAKIT_REQUIRE_RSVG").is_none(),
            "rsvg-convert is required here but not on the PATH"
        );
        eprintln!("rsvg-convert not on the PATH (Debian librsvg2-bin): skipped");
        return None;
    };
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    let pixels = buf[..info.buffer_size()]
        .chunks(channels)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    Some(Image {
        width: info.width as usize,
        pixels,
    })
}

/// A rectangle of the page: x, y, width, height in pixels.
type Rect = [f64; 4];

impl Image {
    /// How many pixels of `rect` are within 40 (per channel) of `rgb`.
    fn count(&self, rect: Rect, rgb: [u8; 3]) -> usize {
        let (x0, y0) = (rect[0] as usize, rect[1] as usize);
        let (x1, y1) = ((rect[0] + rect[2]) as usize, (rect[1] + rect[3]) as usize);
        let near = |p: &[u8; 3]| (0..3).all(|i| p[i].abs_diff(rgb[i]) <= 40);
        (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .filter(|&(x, y)| near(&self.pixels[y * self.width + x]))
            .count()
    }
}

/// The panels of a figure, read from the SVG: each `<g transform="translate(X Y)">`
/// followed by its clip rectangle's width and height.
fn panels(svg: &str) -> Vec<Rect> {
    let num = |s: &str, key: &str| -> f64 {
        let at = s.find(key).unwrap() + key.len();
        let end = s[at..].find(['"', ' ', ')']).unwrap();
        s[at..at + end].parse().unwrap()
    };
    svg.split(r#"<g transform="translate("#)
        .skip(1)
        .map(|g| {
            let (x, rest) = g.split_once(' ').unwrap();
            let y: f64 = rest[..rest.find(')').unwrap()].parse().unwrap();
            [
                x.parse().unwrap(),
                y,
                num(g, "width=\""),
                num(g, "height=\""),
            ]
        })
        .collect()
}

const BLUE: [u8; 3] = [0x2a, 0x6f, 0xdb];
const RED: [u8; 3] = [0xd6, 0x27, 0x28];
const ORANGE: [u8; 3] = [0xff, 0x7f, 0x0e];
const GREEN: [u8; 3] = [0x2c, 0xa0, 0x2c];
const GREY: [u8; 3] = [0x55, 0x55, 0x55];
const BLACK: [u8; 3] = [0x11, 0x11, 0x11];

#[test]
fn the_keil_picture_shows_its_caption() {
    let d = common::dir("keil");
    let svg = d.join("k.svg");
    let v = tetrakit(&[
        "keil",
        "--beta",
        "1.158",
        "--json",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    // The caption states the verdicts of the JSON and the weights' difference.
    assert_eq!(
        (v["xy_in_skeleton"].as_bool(), v["xy_in_mwt"].as_bool()),
        (Some(true), Some(false))
    );
    assert!(
        text.contains("is in the β-skeleton") && text.contains("and not in the MWT"),
        "{text}"
    );
    let diff = v["weight_with_xy"].as_f64().unwrap() - v["weight_without_xy"].as_f64().unwrap();
    assert!(text.contains(&format!("xy costs {diff:.6} more")), "{text}");
    let p = panels(&text);
    assert_eq!(p.len(), 3, "{p:?}");
    let Some(img) = render(&svg) else { return };
    // (a): the MWT, xy, the best triangulation with xy, and the boxes of (b) and (c).
    for (name, c) in [
        ("MWT", BLUE),
        ("xy", RED),
        ("with xy", ORANGE),
        ("boxes", GREEN),
    ] {
        assert!(img.count(p[0], c) > 20, "(a) lacks {name}");
    }
    // (b): around x, the fan crossing xy and xy itself, and x.
    for (name, c) in [("fan", BLUE), ("xy", RED), ("x", BLACK)] {
        assert!(img.count(p[1], c) > 20, "(b) lacks {name}");
    }
    // (c): the sites and the edges across.
    for (name, c) in [("sites", BLACK), ("edges across", ORANGE)] {
        assert!(img.count(p[2], c) > 20, "(c) lacks {name}");
    }
}

#[test]
fn the_keil_picture_of_a_too_small_construction_says_so() {
    let d = common::dir("keil-small");
    let svg = d.join("k.svg");
    let v = tetrakit(&[
        "keil",
        "--beta",
        "1.158",
        "--n",
        "3",
        "--json",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(v["xy_in_mwt"].as_bool(), Some(true));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("and in the MWT") && text.contains("needs more (Lemma 5.8"),
        "{text}"
    );
    assert!(text.contains("xy saves"), "{text}");
    assert!(render(&svg).is_none_or(|img| img.count([0.0, 0.0, 400.0, 400.0], BLUE) > 20));
}

#[test]
fn edge_pictures_show_edges_and_sites() {
    let d = common::dir("edges");
    let pts = d.join("p.xyz");
    run(&[
        "generate",
        "points2d",
        "--n",
        "40",
        "-o",
        pts.to_str().unwrap(),
    ]);
    for cmd in [&["mwt"][..], &["skeleton", "--beta", "1"]] {
        let svg = d.join(format!("{}.svg", cmd[0]));
        let mut args = cmd.to_vec();
        args.extend([
            pts.to_str().unwrap(),
            "--json",
            "--output",
            svg.to_str().unwrap(),
        ]);
        let v = tetrakit(&args);
        let text = std::fs::read_to_string(&svg).unwrap();
        let lines = text.matches(r#"<line class="edge""#).count() as u64;
        assert_eq!(
            Some(lines),
            v["edges"].as_u64(),
            "{}: one line per edge",
            cmd[0]
        );
        assert_eq!(text.matches(r#"class="site""#).count(), 40);
        assert!(
            text.contains(&format!(">40 sites, {lines} edges<")),
            "{}",
            cmd[0]
        );
        let Some(img) = render(&svg) else { return };
        let all = [
            0.0,
            0.0,
            img.width as f64,
            (img.pixels.len() / img.width) as f64,
        ];
        assert!(
            img.count(all, GREY) > 100 && img.count(all, BLACK) > 40 * 10,
            "{}",
            cmd[0]
        );
    }
}
