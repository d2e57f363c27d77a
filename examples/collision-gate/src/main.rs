//! `cargo run --release`: the survey of collision's ray casts against
//! rayoracle's exact oracle, as Markdown.

fn main() {
    for s in collision_gate::survey() {
        println!("{}", s.findings());
    }
}
