//! Arbitrary points (as in the `reconstruct` target) through `Triangulation::new`: the
//! invariant checker passes (valid, Delaunay under the symbolic perturbation, checked
//! exactly), and the input reversed gives the same vertex positions, triangles and twins
//! (the triangulation is canonical), or the same kind of error. Divided and conquered in 2
//! and 4 parts (`Triangulation::new_divided`, merge seams of every kind the input makes),
//! it gives the same vertices, input indices and triangles, in another layout.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt::internals::{check_delaunay, FlatArrays};
use sigdt::Triangulation;

fuzz_target!(|data: &[u8]| {
    let points = sigdt_fuzz::points(data);
    let reversed: Vec<_> = points.iter().rev().copied().collect();
    match (Triangulation::new(&points), Triangulation::new(&reversed)) {
        // The same kind of error (it names the first bad point, which reversing changes).
        (Err(a), Err(b)) => assert_eq!(std::mem::discriminant(&a), std::mem::discriminant(&b)),
        (Ok(dt), Ok(other)) => {
            check_delaunay(&dt).unwrap();
            let (a, b) = (FlatArrays::of(&dt), FlatArrays::of(&other));
            for halvings in [1, 2] {
                let divided = Triangulation::new_divided(&points, halvings).unwrap();
                check_delaunay(&divided).unwrap();
                let c = FlatArrays::of(&divided);
                assert_eq!((&a.points, &a.input_index), (&c.points, &c.input_index));
                assert_eq!(dt.duplicates(), divided.duplicates());
                assert_eq!(a.triangle_set(), c.triangle_set());
            }
            assert_eq!((a.points, a.triangles, a.halfedges), (b.points, b.triangles, b.halfedges));
        }
        (a, b) => panic!("forward ok: {}, reversed ok: {}", a.is_ok(), b.is_ok()),
    }
});

