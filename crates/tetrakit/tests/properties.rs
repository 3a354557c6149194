//! Property tests (proptest) where the input space is large: predicate identities, the
//! filtered paths against the exact predicate, symmetric segment tests, detection against
//! the brute-force oracle (with shrinking to a minimal counterexample), and exact I/O.

use proptest::prelude::*;
use tetrakit::control::Control;
use tetrakit::detect::Options;
use tetrakit::detect::{detect, oracle::forms_tetrahedralization};
use tetrakit::generate::{random_flips, tetrahedralize_points};
use tetrakit::geom::{Frame, Point3, cones_overlap, orient3d, segments_meet};

/// Points that are either small integers (degenerate configurations are frequent) or
/// arbitrary in-range reals.
fn point() -> impl Strategy<Value = Point3> {
    prop_oneof![
        prop::array::uniform3(-3i32..4).prop_map(|a| a.map(f64::from)),
        prop::array::uniform3(-1e3f64..1e3),
        prop::array::uniform3(0i32..5).prop_map(|a| a.map(|x| f64::from(x) * 0.1)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn orient3d_is_antisymmetric(a in point(), b in point(), c in point(), d in point()) {
        let o = orient3d(&a, &b, &c, &d);
        prop_assert_eq!(orient3d(&b, &a, &c, &d), -o);
        prop_assert_eq!(orient3d(&a, &c, &b, &d), -o);
        prop_assert_eq!(orient3d(&b, &c, &d, &a), -o);
    }

    #[test]
    fn filtered_paths_are_exact(v in point(), a in point(), b in point(), c in point()) {
        let f = Frame::new(&v);
        let (da, db, dc) = (f.dir(&a), f.dir(&b), f.dir(&c));
        let exact = orient3d(&v, &a, &b, &c);
        prop_assert_eq!(f.sign(&a, &b, &c, &da, &db, &dc), exact);
        prop_assert_eq!(f.side(&f.plane(&da, &db), &a, &b, &c, &dc), exact);
    }

    #[test]
    fn cone_overlap_is_symmetric_and_reflexive(v in point(), a in prop::array::uniform3(point()), b in prop::array::uniform3(point())) {
        prop_assume!(orient3d(&v, &a[0], &a[1], &a[2]) != 0 && orient3d(&v, &b[0], &b[1], &b[2]) != 0);
        prop_assert_eq!(cones_overlap(&v, &a, &b), cones_overlap(&v, &b, &a));
        prop_assert!(cones_overlap(&v, &a, &a));
        // The point reflection of a cone through its apex never meets it. Only exact
        // reflections count: a rounded one of a nearly flat cone may really overlap it.
        let exact_sub = |p: f64, q: f64| {
            let x = p - q;
            let bv = p - x;
            let av = x + bv;
            ((p - av) + (bv - q) == 0.0).then_some(x)
        };
        let r: Option<Vec<Point3>> = a
            .iter()
            .map(|p| Some([exact_sub(2.0 * v[0], p[0])?, exact_sub(2.0 * v[1], p[1])?, exact_sub(2.0 * v[2], p[2])?]))
            .collect();
        if let Some(r) = r {
            prop_assert!(!cones_overlap(&v, &a, &[r[0], r[1], r[2]]));
        }
    }

    #[test]
    fn segment_meeting_is_symmetric(a in point(), b in point(), c in point(), d in point()) {
        prop_assume!(a != b && c != d);
        prop_assert_eq!(segments_meet(&a, &b, &c, &d).is_some(), segments_meet(&c, &d, &a, &b).is_some());
        prop_assert_eq!(segments_meet(&a, &b, &c, &d), segments_meet(&b, &a, &d, &c));
    }
}

/// Any coordinate the readers take: reals of every magnitude in [2^-142, 2^201], small
/// integers and both zeros.
fn coordinate() -> impl Strategy<Value = f64> {
    let scaled = (1.0f64..2.0, any::<bool>(), -142i32..201)
        .prop_map(|(m, negative, e)| m * 2f64.powi(e) * if negative { -1.0 } else { 1.0 });
    prop_oneof![
        -1e6f64..1e6,
        scaled,
        (-50i32..50).prop_map(f64::from),
        Just(-0.0),
        Just(0.0)
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    /// Edge sets near a tetrahedralization (some edges dropped, some added) on small
    /// degenerate point sets: detect agrees with the oracle.
    #[test]
    fn detect_agrees_with_oracle(
        pts in prop::collection::btree_set(prop::array::uniform3(0i32..3), 5..9),
        flips in 0usize..20,
        seed in any::<u64>(),
        drop in prop::collection::vec(any::<prop::sample::Index>(), 0..3),
        add in prop::collection::vec((0usize..9, 0usize..9), 0..3),
    ) {
        let pts: Vec<Point3> = pts.into_iter().map(|a| a.map(f64::from)).collect();
        let mut t = tetrahedralize_points(pts, seed);
        prop_assume!(!t.tets.is_empty());
        random_flips(&mut t, flips, seed);
        let mut e = t.edges();
        for i in &drop {
            if !e.is_empty() {
                e.remove(i.index(e.len()));
            }
        }
        let n = t.points.len();
        for &(a, b) in &add {
            let (a, b) = ((a % n) as u32, (b % n) as u32);
            let key = [a.min(b), a.max(b)];
            if a != b && !e.contains(&key) {
                e.push(key);
            }
        }
        let d = detect(&t.points, &e, &Options::default(), &Control::new()).unwrap();
        prop_assert_eq!(d.is_yes(), forms_tetrahedralization(&t.points, &e), "{:?}", d.answer.witness());
    }

    /// Writing and reading a mesh gives back the same bits: reals, integers, signed
    /// zeros and magnitudes across the whole exactly supported range (written with an
    /// exponent below 10^-5 and from 10^16 on).
    #[test]
    fn io_round_trip_is_exact(mut pts in prop::collection::vec(prop::array::uniform3(coordinate()), 4..20)) {
        // Distinct points (the readers refuse repeats; -0 repeats 0).
        let mut seen = Vec::new();
        pts.retain(|p| !seen.contains(p) && { seen.push(*p); true });
        prop_assume!(pts.len() >= 4);
        let dir = tempfile::Builder::new().prefix("tetrakit-prop-").tempdir().unwrap();
        let path = dir.path().join("p.ele");
        tetrakit::io::write_mesh(&path, &pts, &[[0, 1, 2, 3]], 1).unwrap();
        let back = tetrakit::io::read_input(&path);
        let back = back.unwrap();
        prop_assert_eq!(back.points.iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>(), pts.iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>());
    }
}
