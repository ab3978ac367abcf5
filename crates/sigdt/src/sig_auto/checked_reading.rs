//! The first reading checked and mended (steps 11–14 of `docs/sig-auto.md`): the sampling
//! check, the outliers it was wired through cut out, the coarse reading where its curves
//! break, and the samples left out beside the curves put back.
use super::coarse_reading;
use super::continuation::MAX_SAMPLED_TURN;
use super::reading::Reading;
use super::{
    finish, first_reading::read, network_reading, outlier_vertices, skipped_samples,
    wired_outliers, Facts, Kind,
};
use crate::result::{LeftOutReason, Reconstruction, Status};
use crate::sampling_check::{Finding, FindingKind, DEPTH_RATIO};

/// The reading, checked, with the wired-in outliers cut and the coarse reading where the
/// check finds the curves broken (steps 11–13 of the module docs).
pub(super) fn checked_reading(facts: &Facts) -> Reconstruction {
    let (dt, steps) = (facts.dt, facts.steps);
    let mut rec = read(facts);
    if rec.status == Status::Network {
        return rec; // a whole network
    }
    if steps.wired_outliers && rec.diagnosis.iter().any(|f| f.kind == FindingKind::DoublesBack) {
        if let Some(cut) = without_wired_outliers(facts, &rec) {
            rec = cut;
        }
    }
    // The zigzag test alone (status `noisy`) does not call for another reading: it also
    // fires on exact readings of jagged polygons given by their vertices.
    let broken = curves_fail(&rec.diagnosis) || matches!(rec.status, Status::SculptingStuck { .. });
    // Curves that meet break every reading through all points: where they read as a
    // network, that is the reading, and no coarser one is needed.
    if let Some(network) = broken.then(|| network_reading(facts, &rec)).flatten() {
        return network;
    }
    if !(steps.coarse && broken) {
        return rec;
    }
    let left_out = outlier_vertices(&rec, &dt.vertex_of_inputs());
    let Some(spacing) = facts.spacing else { return rec };
    match coarse_reading::coarse_reading(dt, steps, &left_out, spacing) {
        Some(fine) => {
            let pairs = chain_pairs(fine.loops.iter().map(|l| (l.as_slice(), true)));
            // Threaded through noisy points, the loops zigzag where the noise does: the
            // status says so (step 10's test), so that a noisy outline is never silent.
            let zigzags = Reading::new(dt, &pairs).zigzags(MAX_SAMPLED_TURN.cos());
            let kind = if zigzags { Kind::Zigzags { open_too: false } } else { Kind::Curves };
            finish(facts, pairs, Vec::new(), &fine.outliers, rec.stats, kind)
        }
        None => rec,
    }
}

/// `rec` with the points it left out as outliers that lie within the sampling of its curves
/// put back (`skipped_samples`), checked again; `rec` itself when there are none.
pub(super) fn with_skipped_samples(facts: &Facts, rec: Reconstruction) -> Reconstruction {
    if !rec.diagnosis.iter().any(|f| f.kind == FindingKind::OutliersOnCurve) {
        return rec;
    }
    let dt = facts.dt;
    let vertex_of = dt.vertex_of_inputs();
    let mut outliers = outlier_vertices(&rec, &vertex_of);
    outliers.sort_unstable();
    let pairs: Vec<[u32; 2]> =
        rec.edges.iter().map(|&[i, j]| [vertex_of[i], vertex_of[j]]).collect();
    let mut reading = Reading::new(dt, &pairs);
    let back = skipped_samples::put_back_skipped(&mut reading, &outliers);
    if back.is_empty() {
        return rec;
    }
    outliers.retain(|v| back.binary_search(v).is_err());
    edited(facts, &rec, reading.pairs(), &outliers)
}

/// The result of `pairs`, an edit of `rec`'s reading that left out `outliers` (vertices of
/// `dt`), checked again. It keeps `rec`'s points left inside, and its status `noisy`: cutting
/// an outlier out or putting a sample back does not straighten a zigzag elsewhere.
fn edited(
    facts: &Facts,
    rec: &Reconstruction,
    pairs: Vec<[u32; 2]>,
    outliers: &[u32],
) -> Reconstruction {
    let inside = rec.left_out.iter().filter(|l| l.reason == LeftOutReason::Inside);
    let kind = match rec.status {
        Status::Noisy => Kind::Zigzags { open_too: true },
        _ => Kind::Curves,
    };
    let inside = inside.map(|l| l.index).collect();
    finish(facts, pairs, inside, outliers, rec.stats, kind)
}

/// Whether `findings` say the reading's curves break the sampling condition by enough to
/// read them again: any finding but outliers on the curves (the curves passed and a point
/// beside them was dropped; the coarse reading threads every point back in anyway), noise
/// that moves the area (which no other reading through the same points takes away), and
/// samples less than [`DEPTH_RATIO`] deep in an edge's disk (reported, but what noise
/// leaves there a coarser reading does not remove: it lost good readings of noisy
/// outlines), and open ends that meet (a coarser reading closes open curves that should
/// stay open: it lost three of `data/curves`; `docs/sig-auto.md`).
pub(super) fn curves_fail(findings: &[Finding]) -> bool {
    findings.iter().any(fails)
}

/// Whether a finding of the sampling check says the curves are not the points' curves
/// (rather than a doubt about some points or the ends).
pub(super) fn fails(finding: &Finding) -> bool {
    match finding.kind {
        FindingKind::OutliersOnCurve | FindingKind::NoisyArea | FindingKind::EndsMeet => false,
        FindingKind::PassesOverSamples => finding.worst >= DEPTH_RATIO,
        _ => true,
    }
}

/// `rec` with the points where it doubles back left out as outliers (`wired_outliers`),
/// checked again; `None` when there is nothing to cut or sculpting got stuck.
fn without_wired_outliers(facts: &Facts, rec: &Reconstruction) -> Option<Reconstruction> {
    if matches!(rec.status, Status::SculptingStuck { .. }) {
        return None;
    }
    let dt = facts.dt;
    let vertex_of = dt.vertex_of_inputs();
    let as_vertices = |c: &Vec<usize>| c.iter().map(|&i| vertex_of[i]).collect::<Vec<u32>>();
    let mut curves: Vec<(Vec<u32>, bool)> =
        rec.loops.iter().map(|l| (as_vertices(l), true)).collect();
    curves.extend(rec.paths.iter().map(|p| (as_vertices(p), false)));
    let cut = wired_outliers::cut_wired_outliers(dt, &mut curves);
    if cut.is_empty() {
        return None;
    }
    let mut outliers = outlier_vertices(rec, &vertex_of);
    outliers.extend(cut);
    let pairs = chain_pairs(curves.iter().map(|(c, closed)| (c.as_slice(), *closed)));
    Some(edited(facts, rec, pairs, &outliers))
}

/// The edges of vertex sequences, each closed (the last joins the first) or open.
fn chain_pairs<'a>(chains: impl Iterator<Item = (&'a [u32], bool)>) -> Vec<[u32; 2]> {
    chains
        .flat_map(|(c, closed)| {
            let n = c.len();
            let edges = if closed { n } else { n.saturating_sub(1) };
            (0..edges).map(move |k| [c[k], c[(k + 1) % n]])
        })
        .collect()
}
