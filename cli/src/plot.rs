//! The error-against-time plot of one kernel, as SVG (plotters).

use plotters::prelude::*;
use rayoracle::report::Point;

/// An SVG plot of `points`: time per ray (log scale) across, worst bits of
/// error up, one labelled point per variant. The Pareto front is filled and
/// joined by a line, the others hollow. A variant that misclassified a case
/// has no finite error to plot; it is drawn as a cross in a band above the
/// axis range, so that the correctly classified variants keep the whole
/// height. Labels are placed where they overlap no other label.
pub fn svg(kernel: &str, points: &[Point]) -> String {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (720, 480)).into_drawing_area();
        // Drawing into a String cannot fail; the results are ignored.
        let _ = draw(&root, kernel, points);
        let _ = root.present();
    }
    out
}

/// The approximate box of a label of `n` characters at 14 px sans-serif.
const CHAR_PX: i32 = 7;
const LINE_PX: i32 = 14;

/// Where a label goes, relative to its point: the first of a few places
/// whose box overlaps none of `placed` (pixel boxes `[x0, y0, x1, y1]`),
/// or the first place if all overlap. The chosen box is added to `placed`.
fn place_label(at: (i32, i32), chars: usize, placed: &mut Vec<[i32; 4]>) -> (i32, i32) {
    let w = CHAR_PX * chars as i32;
    let offsets = [
        (9, -14),
        (9, 4),
        (-9 - w, -14),
        (-9 - w, 4),
        (9, -30),
        (9, 20),
        (-9 - w, -30),
        (-9 - w, 20),
    ];
    let boxed = |(dx, dy): (i32, i32)| {
        let (x, y) = (at.0 + dx, at.1 + dy);
        [x, y, x + w, y + LINE_PX]
    };
    let overlaps = |b: [i32; 4]| {
        placed
            .iter()
            .any(|p| b[0] < p[2] && p[0] < b[2] && b[1] < p[3] && p[1] < b[3])
    };
    let chosen = offsets
        .into_iter()
        .find(|&o| !overlaps(boxed(o)))
        .unwrap_or(offsets[0]);
    placed.push(boxed(chosen));
    chosen
}

fn draw(
    root: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    kernel: &str,
    points: &[Point],
) -> Result<(), Box<dyn std::error::Error>> {
    root.fill(&WHITE)?;
    let finite = |x: f64| x.is_finite() && x > 0.0;
    let shown: Vec<&Point> = points.iter().filter(|p| finite(p.ns_per_ray)).collect();
    let ns: Vec<f64> = shown.iter().map(|p| p.ns_per_ray).collect();
    let lo = ns.iter().copied().fold(f64::INFINITY, f64::min).min(1.0);
    let hi = ns.iter().copied().fold(0.0, f64::max).max(10.0);
    let classified = |p: &Point| p.mismatches == 0;
    let top = shown
        .iter()
        .filter(|p| classified(p))
        .map(|p| p.error_bits)
        .fold(0.0, f64::max)
        .max(4.0)
        * 1.15;
    // Misclassified variants sit in a band above the axis range.
    let band = top * 1.12;
    let y = |p: &Point| if classified(p) { p.error_bits } else { band };
    let mut chart = ChartBuilder::on(root)
        .caption(
            format!("{kernel}: error against run time"),
            ("sans-serif", 20),
        )
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d((lo / 2.0..hi * 2.0).log_scale(), -0.5..band * 1.08)?;
    chart
        .configure_mesh()
        .x_desc("ns per ray (median, one core, log scale)")
        .y_desc("worst max bits of error, every family")
        .y_label_formatter(&|b| {
            if *b > top {
                String::new()
            } else {
                format!("{b:.0}")
            }
        })
        .draw()?;
    let mut front: Vec<&Point> = shown.iter().copied().filter(|p| p.front).collect();
    front.sort_by(|a, b| a.ns_per_ray.total_cmp(&b.ns_per_ray));
    chart
        .draw_series(LineSeries::new(
            front.iter().map(|p| (p.ns_per_ray, y(p))),
            BLUE.stroke_width(2),
        ))?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
    // Legend entries for the three markers: empty series, labels only.
    let none = || std::iter::empty::<EmptyElement<(f64, f64), SVGBackend<'_>>>();
    chart
        .draw_series(none())?
        .label("on the front")
        .legend(|(x, y)| Circle::new((x + 10, y), 6, BLUE.filled()));
    chart
        .draw_series(none())?
        .label("beaten on both axes")
        .legend(|(x, y)| Circle::new((x + 10, y), 6, RED.stroke_width(2)));
    chart
        .draw_series(none())?
        .label("misclassified cases (above the axis)")
        .legend(|(x, y)| Cross::new((x + 10, y), 6, RED.stroke_width(2)));
    let mut placed = Vec::new();
    let mut by_x = shown.clone();
    by_x.sort_by(|a, b| a.ns_per_ray.total_cmp(&b.ns_per_ray));
    for p in by_x {
        let label = if p.mismatches > 0 {
            format!("{} ({} misclassified)", p.variant, p.mismatches)
        } else {
            p.variant.clone()
        };
        let at = chart.backend_coord(&(p.ns_per_ray, y(p)));
        let offset = place_label(at, label.chars().count(), &mut placed);
        let text = Text::new(label, offset, ("sans-serif", 14));
        let spot = EmptyElement::at((p.ns_per_ray, y(p)));
        if !classified(p) {
            chart.draw_series(std::iter::once(
                spot + Cross::new((0, 0), 6, RED.stroke_width(2)) + text,
            ))?;
        } else if p.front {
            chart.draw_series(std::iter::once(
                spot + Circle::new((0, 0), 6, BLUE.filled()) + text,
            ))?;
        } else {
            chart.draw_series(std::iter::once(
                spot + Circle::new((0, 0), 6, RED.stroke_width(2)) + text,
            ))?;
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::MiddleRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use rayoracle::report::{Point, pareto};

    /// Where each variant lands: the circles, the crosses, the front's line
    /// and the labels' places, for three points with fixed times and
    /// errors. Any change to the axis ranges or the offsets moves them.
    /// The misclassified textbook sits in the band above the axis, so the
    /// one bit between f64 and the reference spans a fifth of the height
    /// (it took a thirtieth when misclassified counted as 32 bits).
    #[test]
    fn the_points_land_where_their_numbers_say() {
        let p = |v: &str, ns, bits, mismatches| Point {
            variant: v.into(),
            ns_per_ray: ns,
            error_bits: bits,
            mismatches,
            front: false,
        };
        let mut pts = pareto(vec![
            p("textbook", 3.0, 32.0, 154),
            p("reference", 60.0, 1.0, 0),
            p("f64", 14.0, 0.0, 0),
        ]);
        // An untimed variant (0 ns) is left out of the plot and its axes.
        pts.push(p("untimed", 0.0, 0.5, 0));
        let s = super::svg("sphere", &pts);
        let lines: Vec<&str> = s.lines().collect();
        let attr = |l: &str, a: &str| {
            let v = l.split(&format!(" {a}=\"")).nth(1).unwrap();
            v[..v.find('"').unwrap()].to_string()
        };
        // Circles at (cx, cy), crosses by their first stroke, the front's
        // line (blue, 2 px) by its points; the legend's markers last.
        let shapes: Vec<String> = lines
            .iter()
            .filter_map(|l| {
                if l.starts_with("<circle") {
                    Some(format!("o {},{}", attr(l, "cx"), attr(l, "cy")))
                } else if l.starts_with("<line")
                    && l.contains("#FF0000")
                    && attr(l, "y1") < attr(l, "y2")
                {
                    Some(format!("x {},{}", attr(l, "x1"), attr(l, "y1")))
                } else if l.starts_with("<polyline") && l.contains("#0000FF") {
                    Some(attr(l, "points"))
                } else {
                    None
                }
            })
            .collect();
        // Each label's text and where it starts.
        let labels: Vec<String> = lines
            .windows(2)
            .filter(|w| {
                w[0].starts_with("<text")
                    && ["textbook (154 misclassified)", "reference", "f64"].contains(&w[1])
            })
            .map(|w| format!("{},{} {}", attr(w[0], "x"), attr(w[0], "y"), w[1]))
            .collect();
        assert_eq!(shapes, PINNED_SHAPES, "{shapes:#?}");
        assert_eq!(labels, PINNED_LABELS, "{labels:#?}");
    }

    const PINNED_SHAPES: [&str; 8] = [
        "278,68 455,388 ",
        "x 272,62",
        "o 455,388",
        "o 623,326",
        "462,208 482,208 ",
        "o 472,223",
        "o 472,238",
        "x 466,247",
    ];
    const PINNED_LABELS: [&str; 3] = [
        "287,54 textbook (154 misclassified)",
        "464,374 f64",
        "632,312 reference",
    ];

    /// The plot names every timed variant; a time that is not a positive
    /// number (not measured) is left off the axis range, and the rest is
    /// still drawn.
    #[test]
    fn every_timed_variant_is_drawn() {
        let p = |v: &str, ns, bits| Point {
            variant: v.into(),
            ns_per_ray: ns,
            error_bits: bits,
            mismatches: 0,
            front: false,
        };
        let s = super::svg(
            "sphere",
            &pareto(vec![p("textbook", 3.0, 32.0), p("reference", 60.0, 1.0)]),
        );
        assert!(s.starts_with("<svg") && s.contains("textbook") && s.contains("Pareto"));
        let pts = vec![
            p("f64", 0.0, 1.0),
            p("exact", f64::INFINITY, 0.0),
            p("reference", 60.0, 1.0),
        ];
        let s = super::svg("sphere", &pareto(pts));
        assert!(s.contains("\nreference\n") && !s.contains("\nexact\n"));
    }

    /// A label goes up and right of its point unless that box is taken;
    /// then below, then to the left.
    #[test]
    fn labels_move_out_of_each_others_way() {
        let mut placed = Vec::new();
        assert_eq!(super::place_label((100, 100), 4, &mut placed), (9, -14));
        assert_eq!(placed, [[109, 86, 137, 100]]);
        assert_eq!(super::place_label((100, 100), 4, &mut placed), (9, 4));
        assert_eq!(super::place_label((100, 100), 2, &mut placed), (-23, -14));
        assert_eq!(super::place_label((300, 100), 4, &mut placed), (9, -14));
        for _ in 0..5 {
            super::place_label((100, 100), 4, &mut placed);
        }
        // Every place taken: the first, overlapping.
        assert_eq!(super::place_label((100, 100), 4, &mut placed), (9, -14));
    }
}
