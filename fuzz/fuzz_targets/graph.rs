//! Arbitrary points (as in the `reconstruct` target) through `sigdt::proximity_graph` for
//! every graph kind (kNN with k = 1..4): either every kind fails alike, or each edge list is
//! `[i, j]`, `i < j < n`, sorted and unique, and SIGDT ⊆ SIGDT2 ⊆ DT, EMST ⊆ DT.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sigdt::{proximity_graph, Edge, GraphKind};
use sigdt_fuzz::assert_edge_list;

fuzz_target!(|data: &[u8]| {
    let points = sigdt_fuzz::points(data);
    let n = points.len();
    let dt = match proximity_graph(&points, GraphKind::Dt) {
        Ok(dt) => dt,
        Err(_) => return,
    };
    assert_edge_list("dt", &dt, n);
    let subset = |a: &[Edge], b: &[Edge]| a.iter().all(|e| b.binary_search(e).is_ok());
    let kinds = [GraphKind::Sig, GraphKind::SigDt, GraphKind::SigDt2, GraphKind::Emst]
        .into_iter()
        .chain((1..=4).map(|k| GraphKind::Knn { k }));
    let mut graphs = Vec::new();
    for kind in kinds {
        let g = proximity_graph(&points, kind).expect("validated");
        assert_edge_list(&kind.to_string(), &g, n);
        graphs.push((kind, g));
    }
    let get = |kind: GraphKind| &graphs.iter().find(|(k, _)| *k == kind).unwrap().1;
    assert!(subset(get(GraphKind::SigDt), get(GraphKind::SigDt2)), "sigdt ⊄ sigdt2");
    assert!(subset(get(GraphKind::SigDt2), &dt), "sigdt2 ⊄ dt");
    assert!(subset(get(GraphKind::Emst), &dt), "emst ⊄ dt");
});
