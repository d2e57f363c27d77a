//! `cargo run --release`: the survey of parry3d's ray casts against
//! rayoracle's exact oracle, as the Markdown in rayoracle's README.

use parry3d_gate::{FAR_1E4, Surveyed, failing, side_by_side, survey};

fn main() {
    let (spheres, planes) = survey();
    // Ball::cast_ray with a pose gives the same bits as cast_local_ray on
    // every case (a test asserts it), so the table shows one of them.
    let shown: Vec<&Surveyed> = spheres
        .iter()
        .filter(|k| k.kernel != "parry3d Ball::cast_ray (posed)")
        .collect();
    println!("### Spheres\n\n{}", side_by_side(&shown));
    println!(
        "### Planes\n\n{}",
        side_by_side(&planes.iter().collect::<Vec<_>>())
    );
    println!("Families failing the gate:\n");
    for k in spheres.iter().chain(&planes) {
        println!("* {}: {:?}", k.kernel, failing(k));
    }
    println!("\nThe claim ({FAR_1E4}):\n");
    for k in &spheres {
        if let Some(f) = k.stats.iter().find(|f| f.family == FAR_1E4) {
            println!(
                "* {}: {} rays, {} wrong hits, {} wrong misses, {} hits compared, max {} / median {} ulps",
                k.kernel, f.cases, f.wrong_hits, f.wrong_misses, f.hits, f.max_ulps, f.median_ulps
            );
        }
    }
}
