//! `cargo run --release`: the survey of bevy_math's ray casts against
//! rayoracle's exact oracle, as Markdown.

fn main() {
    for s in bevy_math_gate::survey() {
        println!("{}", s.findings());
    }
}
