//! The error-against-time plot of one kernel, as SVG (plotters).

use super::Point;
use plotters::prelude::*;

/// An SVG plot of `points`: time per ray (log scale) across, worst bits of
/// error up, one labelled point per variant, the Pareto front filled and
/// joined by a line, the others hollow.
///
/// ```
/// use rayoracle::report::{Point, pareto, svg};
/// let p = |v: &str, ns, bits| Point { variant: v.into(), ns_per_ray: ns, error_bits: bits, mismatches: 0, front: false };
/// let s = svg("sphere", &pareto(vec![p("textbook", 3.0, 32.0), p("reference", 60.0, 1.0)]));
/// assert!(s.starts_with("<svg") && s.contains("textbook") && s.contains("Pareto"));
/// // A time that is not a positive number (not measured) is left off the
/// // axis range, and the rest is still drawn.
/// let s = svg("sphere", &pareto(vec![p("f64", 0.0, 1.0), p("exact", f64::INFINITY, 0.0), p("reference", 60.0, 1.0)]));
/// assert!(s.contains("\nreference\n"));
/// ```
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

fn draw(
    root: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    kernel: &str,
    points: &[Point],
) -> Result<(), Box<dyn std::error::Error>> {
    root.fill(&WHITE)?;
    let finite = |x: f64| x.is_finite() && x > 0.0;
    let ns: Vec<f64> = points
        .iter()
        .map(|p| p.ns_per_ray)
        .filter(|&x| finite(x))
        .collect();
    let lo = ns.iter().copied().fold(f64::INFINITY, f64::min).min(1.0);
    let hi = ns.iter().copied().fold(0.0, f64::max).max(10.0);
    let top = points
        .iter()
        .map(|p| p.error_bits)
        .fold(0.0, f64::max)
        .max(4.0)
        * 1.15;
    let mut chart = ChartBuilder::on(root)
        .caption(
            format!("{kernel}: error against run time (★ Pareto front)"),
            ("sans-serif", 20),
        )
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(56)
        .build_cartesian_2d((lo / 2.0..hi * 2.0).log_scale(), -0.5..top)?;
    chart
        .configure_mesh()
        .x_desc("ns per ray (median, one core, log scale)")
        .y_desc("worst max bits of error, every family")
        .draw()?;
    let mut front: Vec<&Point> = points
        .iter()
        .filter(|p| p.front && finite(p.ns_per_ray))
        .collect();
    front.sort_by(|a, b| a.ns_per_ray.total_cmp(&b.ns_per_ray));
    chart
        .draw_series(LineSeries::new(
            front.iter().map(|p| (p.ns_per_ray, p.error_bits)),
            BLUE.stroke_width(2),
        ))?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
    for p in points.iter().filter(|p| finite(p.ns_per_ray)) {
        let style = if p.front {
            BLUE.filled()
        } else {
            RED.stroke_width(2)
        };
        let label = if p.mismatches > 0 {
            format!("{} ({} misclassified)", p.variant, p.mismatches)
        } else {
            p.variant.clone()
        };
        chart.draw_series(std::iter::once(
            EmptyElement::at((p.ns_per_ray, p.error_bits))
                + Circle::new((0, 0), 6, style)
                + Text::new(label, (9, -14), ("sans-serif", 14)),
        ))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::{Point, pareto};

    /// Where each variant lands: the circles, the front's line and the
    /// labels' places, for three points with fixed times and errors. Any
    /// change to the axis ranges or the offsets moves them.
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
        // Circles at (cx, cy); the front's line (blue, 2 px) by its points.
        let shapes: Vec<String> = lines
            .iter()
            .filter_map(|l| {
                if l.starts_with("<circle") {
                    Some(format!("{},{}", attr(l, "cx"), attr(l, "cy")))
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

    const PINNED_SHAPES: [&str; 5] = [
        "278,91 455,414 ",
        "278,91",
        "623,404",
        "455,414",
        "593,231 613,231 ",
    ];
    const PINNED_LABELS: [&str; 3] = [
        "287,77 textbook (154 misclassified)",
        "632,390 reference",
        "464,400 f64",
    ];
}
