//! `cargo run --release`: the survey of parry3d's ray casts against
//! rayoracle's exact oracle, as Markdown (the table in rayoracle's README).

use parry3d_gate::{FAR_1E4, failing, side_by_side, survey};

fn main() {
    let (spheres, planes) = survey();
    println!("## Spheres\n\n{}", side_by_side(&spheres));
    println!("## Planes\n\n{}", side_by_side(&planes));
    for k in spheres.iter().chain(&planes) {
        println!("{}: fails the gate on {:?}", k.kernel, failing(k));
    }
    for k in &spheres {
        if let Some(f) = k.stats.iter().find(|f| f.family == FAR_1E4) {
            println!(
                "{FAR_1E4}, {}: {} rays, {} hits compared, {} wrong hits, {} wrong misses, max {} / median {} ulps",
                k.kernel, f.cases, f.hits, f.wrong_hits, f.wrong_misses, f.max_ulps, f.median_ulps
            );
        }
    }
}
