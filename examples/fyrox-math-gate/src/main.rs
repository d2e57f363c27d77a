//! `cargo run --release`: the survey of fyrox-math's ray casts against
//! rayoracle's exact oracle, as Markdown.

fn main() {
    for s in fyrox_math_gate::survey() {
        println!("{}", s.findings());
    }
}
