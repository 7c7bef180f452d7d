using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Draws the flights of a scenario file as an SVG: a side view (height against downrange) above a top
    /// view (lateral against downrange), sharing the downrange axis. "Up" is -gravity of the first scenario,
    /// "downrange" the horizontal part of its launch velocity, "lateral" up x downrange (to the left in a
    /// right-handed frame). The ground and every plane are drawn: an unbounded plane as a dashed trace (its
    /// intersection with the view's plane through the origin), a bounded one (a net, a goal mouth) as the
    /// projection of its rectangle. The two axes of a view are scaled separately so short, flat flights stay readable.
    /// </summary>
    internal static class TrajectorySvg
    {
        /// <summary>Which views to draw.</summary>
        internal enum SvgViews
        {
            Both,
            Side,
            Top,
        }

        private const double Width = 900;
        private const double PanelHeight = 280;
        private const double Left = 70, Right = 20, Top = 40, Gap = 70, Bottom = 50;
        /// <summary>Points drawn per flight (on the interpolant).</summary>
        internal const int SamplesPerFlight = 400;

        private static readonly string[] Palette =
        {
            "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22",
        };

        private sealed record View(string Title, string VerticalLabel, Func<Vector3d, double> Vertical, double Y0)
        {
            public double MinA { get; set; }
            public double MaxA { get; set; }
            public double MinB { get; set; }
            public double MaxB { get; set; }
        }

        public static string Draw(IReadOnlyList<FlightResult> results, SvgViews views = SvgViews.Both)
        {
            Scenario first = results[0].Scenario;
            Vector3d up = first.Model.Up.LengthSquared > 0 ? first.Model.Up : Vector3d.UnitZ;
            Vector3d launch = first.Initial.Velocity;
            Vector3d forward = (launch - up * Vector3d.Dot(launch, up)).NormalizedOrZero();
            if (forward.LengthSquared == 0)
            {
                forward = Vector3d.Cross(up, Math.Abs(up.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY).NormalizedOrZero();
            }

            // A launch aimed a little off a frame axis (a curling free kick) is drawn along that axis, so goal
            // lines and nets stay square to the page.
            foreach (Vector3d axis in new[] { Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ, -Vector3d.UnitX, -Vector3d.UnitY, -Vector3d.UnitZ })
            {
                if (Math.Abs(Vector3d.Dot(axis, up)) < 1e-9 && Vector3d.Dot(axis, forward) > Math.Cos(Math.PI / 6))
                {
                    forward = axis;
                    break;
                }
            }

            Vector3d lateral = Vector3d.Cross(up, forward);
            Func<Vector3d, double> along = p => Vector3d.Dot(p, forward);

            var side = new View("side view", "height (m)", p => Vector3d.Dot(p, up), Top);
            var top = new View("top view", "lateral, + = up x downrange (m)", p => Vector3d.Dot(p, lateral), views == SvgViews.Top ? Top : Top + PanelHeight + Gap);
            var drawn = views switch
            {
                SvgViews.Side => new[] { side },
                SvgViews.Top => new[] { top },
                _ => new[] { side, top },
            };

            var paths = results.Select(r => ResultWriter.Sample(r, SamplesPerFlight).Select(s => s.Position).ToList()).ToList();
            double groundHeight = first.Ground is NamedPlane g0 ? Vector3d.Dot(g0.Point, up) : 0;

            // Extents: the flights, the ground, and the finite parts of bounded planes.
            var points = paths.SelectMany(p => p).ToList();
            foreach (FlightResult r in results)
            {
                foreach (NamedPlane plane in r.Scenario.Planes)
                {
                    if (plane.Bounds is PlaneBounds b)
                    {
                        points.AddRange(Corners(plane, b).Where(c => c.IsFinite));
                    }
                }
            }

            var shapes = results.SelectMany(r => r.Scenario.Shapes ?? Array.Empty<ContactShape>()).ToList();
            foreach (ContactShape shape in shapes)
            {
                points.AddRange(BoxCorners(shape.BoundsMin, shape.BoundsMax).Where(c => c.IsFinite));
            }

            double minA = Math.Min(0, points.Min(along)), maxA = points.Max(along);
            foreach (FlightResult r in results)
            {
                foreach (NamedPlane plane in r.Scenario.Planes)
                {
                    // A plane across the flight (a net, a line) should be in the picture even if the ball stops short.
                    double nf = Vector3d.Dot(plane.Normal, forward);
                    if (Math.Abs(nf) > 0.5)
                    {
                        double a = Vector3d.Dot(plane.Point, plane.Normal) / nf;
                        minA = Math.Min(minA, a);
                        maxA = Math.Max(maxA, a);
                    }
                }
            }

            Pad(ref minA, ref maxA);
            side.MinA = top.MinA = minA;
            side.MaxA = top.MaxA = maxA;
            double minB = Math.Min(groundHeight, points.Min(side.Vertical)), maxB = points.Max(side.Vertical);
            Pad(ref minB, ref maxB);
            side.MinB = minB;
            side.MaxB = maxB;
            minB = points.Min(top.Vertical);
            maxB = points.Max(top.Vertical);
            Pad(ref minB, ref maxB);
            top.MinB = minB;
            top.MaxB = maxB;

            var svg = new StringBuilder();
            double legendTop = drawn[^1].Y0 + PanelHeight + Bottom;
            double height = legendTop + 16 * (results.Count + 1) + 10;
            svg.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{F(Width)}\" height=\"{F(height)}\" viewBox=\"0 0 {F(Width)} {F(height)}\" font-family=\"sans-serif\" font-size=\"12\">\n");
            svg.Append($"<rect width=\"{F(Width)}\" height=\"{F(height)}\" fill=\"white\"/>\n");

            foreach (View view in drawn)
            {
                Frame(svg, view);
                if (view == side && first.Ground is NamedPlane ground)
                {
                    Trace(svg, view, ground, forward, up, "#6b4f2a", "3,0", 1.5);
                }

                foreach (NamedPlane plane in results.SelectMany(r => r.Scenario.Planes).GroupBy(p => p.Name).Select(p => p.First()))
                {
                    Vector3d normal2 = view == side ? up : lateral;
                    if (plane.Bounds is PlaneBounds b)
                    {
                        BoundedPlane(svg, view, plane, b, along);
                    }
                    else
                    {
                        Trace(svg, view, plane, forward, normal2, "#888888", "6,4", 1);
                    }
                }

                foreach (ContactShape shape in shapes)
                {
                    Shape(svg, view, shape, along);
                }

                for (int i = 0; i < results.Count; i++)
                {
                    string colour = Palette[i % Palette.Length];
                    var line = new StringBuilder();
                    foreach (Vector3d p in paths[i])
                    {
                        (double x, double y) = Map(view, along(p), view.Vertical(p));
                        line.Append(F(x)).Append(',').Append(F(y)).Append(' ');
                    }

                    svg.Append($"<polyline fill=\"none\" stroke=\"{colour}\" stroke-width=\"1.8\" points=\"{line.ToString().TrimEnd()}\"/>\n");
                    FlightResult r = results[i];
                    if (r.Landing is FlightState landing)
                    {
                        (double x, double y) = Map(view, along(landing.Position), view.Vertical(landing.Position));
                        svg.Append($"<circle cx=\"{F(x)}\" cy=\"{F(y)}\" r=\"3.5\" fill=\"{colour}\"/>\n");
                    }

                    foreach (Crossing c in r.Crossings)
                    {
                        (double x, double y) = Map(view, along(c.State.Position), view.Vertical(c.State.Position));
                        svg.Append($"<rect x=\"{F(x - 3)}\" y=\"{F(y - 3)}\" width=\"6\" height=\"6\" fill=\"white\" stroke=\"{colour}\" stroke-width=\"1.5\"/>\n");
                    }

                    foreach (FlightEvent c in r.Contacts ?? Array.Empty<FlightEvent>())
                    {
                        // A contact with a shape: a diamond at the ball's centre.
                        (double x, double y) = Map(view, along(c.State.Position), view.Vertical(c.State.Position));
                        svg.Append($"<polygon points=\"{F(x)},{F(y - 4.5)} {F(x + 4.5)},{F(y)} {F(x)},{F(y + 4.5)} {F(x - 4.5)},{F(y)}\" fill=\"white\" stroke=\"{colour}\" stroke-width=\"1.5\"/>\n");
                    }
                }
            }

            // Legend, under the views.
            double legendY = legendTop;
            for (int i = 0; i < results.Count; i++)
            {
                string colour = Palette[i % Palette.Length];
                double x = Left;
                svg.Append($"<line x1=\"{F(x)}\" y1=\"{F(legendY - 4)}\" x2=\"{F(x + 22)}\" y2=\"{F(legendY - 4)}\" stroke=\"{colour}\" stroke-width=\"2.5\"/>\n");
                svg.Append($"<text x=\"{F(x + 28)}\" y=\"{F(legendY)}\">{Escape(results[i].Scenario.Name)}</text>\n");
                legendY += 16;
            }

            svg.Append($"<text x=\"{F(Left)}\" y=\"{F(legendY)}\" fill=\"#555\" font-size=\"11\">dot: landing; square: plane crossing; dashed: unbounded plane; bold: a plane's bounds (net, goal)" +
                (shapes.Count > 0 ? "; grey solid: a shape; diamond: contact with a shape" : string.Empty) + "</text>\n");
            svg.Append("</svg>\n");
            return svg.ToString();
        }

        private const string ShapeFill = "#777777";

        // A contact shape in the view (issue 40): a box, rectangle or net mesh as the outline of its corners; a sphere as a circle; a capsule
        // or cylinder as a thick line along its axis (a circle where its axis points out of the view: the net cord seen from
        // the side); a torus as its cross-section by the view's plane through its centre (the two circles of its tube; seen
        // along its axis, the ring).
        private static void Shape(StringBuilder svg, View view, ContactShape shape, Func<Vector3d, double> along)
        {
            switch (shape)
            {
                case CapsuleShape c:
                    Rod(svg, view, c.EndA, c.EndB, c.RadiusM, along, round: true);
                    return;
                case CylinderShape c:
                    Rod(svg, view, c.EndA, c.EndB, c.RadiusM, along, round: false);
                    return;
                case TorusShape t:
                    Torus(svg, view, t, along);
                    return;
                case SphereShape sphere:
                    Rod(svg, view, sphere.Centre, sphere.Centre, sphere.RadiusM, along, round: true);
                    return;
                default:
                {
                    // A box, rectangle or mesh: the outline of its eight corners as the view sees them (their convex hull).
                    BoxShape box = shape is NetMeshShape mesh ? mesh.Sheet : (BoxShape)shape;
                    var quad = Clip(Hull(box.Corners().Select(p => (A: along(p), B: view.Vertical(p))).ToList()), view, closed: true);
                    if (quad.Count == 0)
                    {
                        return;
                    }

                    string pts = string.Join(" ", quad.Select(q => { (double x, double y) = Map(view, q.A, q.B); return F(x) + "," + F(y); }));
                    string fill = shape is NetMeshShape ? "fill-opacity=\"0.25\"" : "fill-opacity=\"0.6\"";
                    svg.Append($"<polygon points=\"{pts}\" fill=\"{ShapeFill}\" {fill} stroke=\"#333\" stroke-width=\"1\"/>\n");
                    return;
                }
            }
        }

        // The convex hull of points in the view's plane, counter-clockwise (Andrew's monotone chain).
        private static List<(double A, double B)> Hull(List<(double A, double B)> points)
        {
            var sorted = points.Distinct().OrderBy(p => p.A).ThenBy(p => p.B).ToList();
            if (sorted.Count < 3)
            {
                return sorted;
            }

            static double Turn((double A, double B) o, (double A, double B) a, (double A, double B) b) =>
                (a.A - o.A) * (b.B - o.B) - (a.B - o.B) * (b.A - o.A);
            var hull = new List<(double A, double B)>();
            for (int pass = 0; pass < 2; pass++)
            {
                int start = hull.Count;
                foreach (var p in pass == 0 ? sorted : Enumerable.Reverse(sorted))
                {
                    while (hull.Count >= start + 2 && Turn(hull[hull.Count - 2], hull[hull.Count - 1], p) <= 0)
                    {
                        hull.RemoveAt(hull.Count - 1);
                    }

                    hull.Add(p);
                }

                hull.RemoveAt(hull.Count - 1);
            }

            return hull;
        }

        private static void Rod(StringBuilder svg, View view, Vector3d a, Vector3d b, double radius, Func<Vector3d, double> along, bool round)
        {
            (double x0, double y0) = Map(view, along(a), view.Vertical(a));
            (double x1, double y1) = Map(view, along(b), view.Vertical(b));
            (double rx, double ry) = Radii(view, radius);
            double length = Math.Sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0));
            if (length < Math.Max(rx, ry))
            {
                svg.Append($"<ellipse cx=\"{F(0.5 * (x0 + x1))}\" cy=\"{F(0.5 * (y0 + y1))}\" rx=\"{F(rx)}\" ry=\"{F(ry)}\" fill=\"{ShapeFill}\" stroke=\"#333\" stroke-width=\"1\"/>\n");
                return;
            }

            // Thickness across the line: the radius at the view's scale across its direction.
            double across = Math.Abs(x1 - x0) >= Math.Abs(y1 - y0) ? ry : rx;
            svg.Append($"<line x1=\"{F(x0)}\" y1=\"{F(y0)}\" x2=\"{F(x1)}\" y2=\"{F(y1)}\" stroke=\"{ShapeFill}\" stroke-width=\"{F(2 * across)}\" stroke-linecap=\"{(round ? "round" : "butt")}\"/>\n");
        }

        private static void Torus(StringBuilder svg, View view, TorusShape t, Func<Vector3d, double> along)
        {
            double ca = along(t.Centre), cb = view.Vertical(t.Centre);
            (double x, double y) = Map(view, ca, cb);
            (double rx, double ry) = Radii(view, t.TubeRadiusM);
            (double Rx, double Ry) = Radii(view, t.RingRadiusM);
            // The axis's parts along the view's two directions (unit directions: p -> along(p) and p -> Vertical(p) are linear).
            double axisA = along(t.Centre + t.Axis) - ca, axisB = view.Vertical(t.Centre + t.Axis) - cb;
            if (axisA * axisA + axisB * axisB < 0.01)
            {
                // Seen along its axis: the ring.
                svg.Append($"<ellipse cx=\"{F(x)}\" cy=\"{F(y)}\" rx=\"{F(Rx)}\" ry=\"{F(Ry)}\" fill=\"none\" stroke=\"{ShapeFill}\" stroke-width=\"{F(Math.Max(1, rx + ry))}\"/>\n");
                return;
            }

            // The cross-section: the tube's circles at the centre plus and minus the ring radius across the axis, in the view.
            double norm = Math.Sqrt(axisA * axisA + axisB * axisB);
            double ua = -axisB / norm, ub = axisA / norm;
            foreach (double sign in new[] { -1.0, 1.0 })
            {
                (double cx, double cy) = Map(view, ca + sign * ua * t.RingRadiusM, cb + sign * ub * t.RingRadiusM);
                svg.Append($"<ellipse cx=\"{F(cx)}\" cy=\"{F(cy)}\" rx=\"{F(Math.Max(1.5, rx))}\" ry=\"{F(Math.Max(1.5, ry))}\" fill=\"{ShapeFill}\" stroke=\"#333\" stroke-width=\"1\"/>\n");
            }
        }

        // A length in metres as pixels along the view's two axes (they are scaled separately), at least 1.5 px.
        private static (double X, double Y) Radii(View v, double metres)
        {
            double x = metres / (v.MaxA * 0.5 - v.MinA * 0.5) * 0.5 * (Width - Left - Right);
            double y = metres / (v.MaxB * 0.5 - v.MinB * 0.5) * 0.5 * PanelHeight;
            return (Pixel(Math.Max(1.5, x)), Pixel(Math.Max(1.5, y)));
        }

        private static IEnumerable<Vector3d> BoxCorners(Vector3d lo, Vector3d hi)
        {
            for (int i = 0; i < 8; i++)
            {
                yield return new Vector3d((i & 1) == 0 ? lo.X : hi.X, (i & 2) == 0 ? lo.Y : hi.Y, (i & 4) == 0 ? lo.Z : hi.Z);
            }
        }

        private static void Frame(StringBuilder svg, View view)
        {
            double x0 = Left, x1 = Width - Right, y0 = view.Y0, y1 = view.Y0 + PanelHeight;
            svg.Append($"<text x=\"{F(x0)}\" y=\"{F(y0 - 10)}\" font-size=\"14\" font-weight=\"bold\">{view.Title}</text>\n");
            svg.Append($"<rect x=\"{F(x0)}\" y=\"{F(y0)}\" width=\"{F(x1 - x0)}\" height=\"{F(PanelHeight)}\" fill=\"none\" stroke=\"#333\"/>\n");
            foreach (double a in Ticks(view.MinA, view.MaxA))
            {
                (double x, _) = Map(view, a, view.MinB);
                svg.Append($"<line x1=\"{F(x)}\" y1=\"{F(y0)}\" x2=\"{F(x)}\" y2=\"{F(y1)}\" stroke=\"#e4e4e4\"/>\n");
                svg.Append($"<text x=\"{F(x)}\" y=\"{F(y1 + 15)}\" text-anchor=\"middle\">{Label(a)}</text>\n");
            }

            foreach (double b in Ticks(view.MinB, view.MaxB))
            {
                (_, double y) = Map(view, view.MinA, b);
                svg.Append($"<line x1=\"{F(x0)}\" y1=\"{F(y)}\" x2=\"{F(x1)}\" y2=\"{F(y)}\" stroke=\"#e4e4e4\"/>\n");
                svg.Append($"<text x=\"{F(x0 - 6)}\" y=\"{F(y + 4)}\" text-anchor=\"end\">{Label(b)}</text>\n");
            }

            svg.Append($"<text x=\"{F((x0 + x1) / 2)}\" y=\"{F(y1 + 32)}\" text-anchor=\"middle\">downrange (m)</text>\n");
            svg.Append($"<text transform=\"translate({F(x0 - 48)},{F((y0 + y1) / 2)}) rotate(-90)\" text-anchor=\"middle\">{view.VerticalLabel}</text>\n");
        }

        // The plane's trace in the view: points a*forward + b*axis with n.(p - q) = 0.
        private static void Trace(StringBuilder svg, View view, NamedPlane plane, Vector3d forward, Vector3d axis, string colour, string dash, double width)
        {
            double na = Vector3d.Dot(plane.Normal, forward), nb = Vector3d.Dot(plane.Normal, axis), c = Vector3d.Dot(plane.Normal, plane.Point);
            (double A, double B)? p0, p1;
            if (Math.Abs(nb) >= Math.Abs(na))
            {
                if (Math.Abs(nb) < 1e-9)
                {
                    return;
                }

                p0 = (view.MinA, (c - na * view.MinA) / nb);
                p1 = (view.MaxA, (c - na * view.MaxA) / nb);
            }
            else
            {
                p0 = ((c - nb * view.MinB) / na, view.MinB);
                p1 = ((c - nb * view.MaxB) / na, view.MaxB);
            }

            var clipped = Clip(new List<(double A, double B)> { p0.Value, p1.Value }, view, closed: false);
            if (clipped.Count < 2)
            {
                return;
            }

            (double x0, double y0) = Map(view, clipped[0].A, clipped[0].B);
            (double x1, double y1) = Map(view, clipped[^1].A, clipped[^1].B);
            svg.Append($"<line x1=\"{F(x0)}\" y1=\"{F(y0)}\" x2=\"{F(x1)}\" y2=\"{F(y1)}\" stroke=\"{colour}\" stroke-width=\"{F(width)}\" stroke-dasharray=\"{dash}\"/>\n");
            if (plane.Name != "ground")
            {
                svg.Append($"<text x=\"{F(x1 + 3)}\" y=\"{F(Math.Min(y0, y1) + 12)}\" fill=\"#555\" font-size=\"11\">{Escape(plane.Name)}</text>\n");
            }
        }

        private static void BoundedPlane(StringBuilder svg, View view, NamedPlane plane, PlaneBounds bounds, Func<Vector3d, double> along)
        {
            var quad = Corners(plane, bounds).Select(c => (along(c), view.Vertical(c))).ToList();
            quad = Clip(quad, view, closed: true);
            if (quad.Count == 0)
            {
                return;
            }

            string pts = string.Join(" ", quad.Select(q => { (double x, double y) = Map(view, q.Item1, q.Item2); return F(x) + "," + F(y); }));
            svg.Append($"<polygon points=\"{pts}\" fill=\"#444\" fill-opacity=\"0.15\" stroke=\"#222\" stroke-width=\"3\" stroke-linejoin=\"round\"/>\n");
            double labelA = quad.Max(q => q.Item1), labelB = quad.Max(q => q.Item2);
            (double lx, double ly) = Map(view, labelA, labelB);
            svg.Append($"<text x=\"{F(lx + 4)}\" y=\"{F(ly + 12)}\" fill=\"#222\" font-size=\"11\">{Escape(plane.Name)}</text>\n");
        }

        // The rectangle's corners; an unbounded side is cut at 1 km.
        private static IEnumerable<Vector3d> Corners(NamedPlane plane, PlaneBounds b)
        {
            const double Far = 1000;
            double h0 = Math.Max(b.HeightMin, -Far), h1 = Math.Min(b.HeightMax, Far);
            double w0 = Math.Max(b.WidthMin, -Far), w1 = Math.Min(b.WidthMax, Far);
            yield return plane.Point + b.HeightAxis * h0 + b.WidthAxis * w0;
            yield return plane.Point + b.HeightAxis * h1 + b.WidthAxis * w0;
            yield return plane.Point + b.HeightAxis * h1 + b.WidthAxis * w1;
            yield return plane.Point + b.HeightAxis * h0 + b.WidthAxis * w1;
        }

        // Sutherland-Hodgman against the view's data rectangle (an open polyline of two points is a segment).
        private static List<(double A, double B)> Clip(List<(double A, double B)> poly, View v, bool closed)
        {
            var edges = new (Func<(double A, double B), double> Inside, int Axis, double Value)[]
            {
                (p => p.A - v.MinA, 0, v.MinA), (p => v.MaxA - p.A, 0, v.MaxA),
                (p => p.B - v.MinB, 1, v.MinB), (p => v.MaxB - p.B, 1, v.MaxB),
            };
            foreach (var edge in edges)
            {
                var output = new List<(double A, double B)>();
                int n = poly.Count;
                int segments = closed ? n : n - 1;
                for (int i = 0; i < segments; i++)
                {
                    var s = poly[i];
                    var e = poly[(i + 1) % n];
                    double ds = edge.Inside(s), de = edge.Inside(e);
                    if (ds >= 0 && (output.Count == 0 || output[^1] != s))
                    {
                        output.Add(s);
                    }

                    if (ds >= 0 != de >= 0)
                    {
                        double t = ds / (ds - de);
                        output.Add((s.A + (e.A - s.A) * t, s.B + (e.B - s.B) * t));
                    }

                    if (!closed && i == segments - 1 && de >= 0)
                    {
                        output.Add(e);
                    }
                }

                poly = output;
                if (poly.Count == 0)
                {
                    break;
                }
            }

            return poly;
        }

        // Halves throughout: exact (a power of two) and finite even for extents near double.MaxValue. Pixels are
        // clamped to +-1e5 (far outside the page) so every coordinate written is a finite number.
        private static (double X, double Y) Map(View v, double a, double b) =>
            (Pixel(Left + (a * 0.5 - v.MinA * 0.5) / (v.MaxA * 0.5 - v.MinA * 0.5) * (Width - Left - Right)),
             Pixel(v.Y0 + PanelHeight - (b * 0.5 - v.MinB * 0.5) / (v.MaxB * 0.5 - v.MinB * 0.5) * PanelHeight));

        private static double Pixel(double x) => double.IsNaN(x) ? 0 : Math.Max(-1e5, Math.Min(1e5, x));

        private static void Pad(ref double min, ref double max)
        {
            if (!double.IsFinite(min) || !double.IsFinite(max))
            {
                // A projection overflowed (a flight near double.MaxValue): draw a unit axis rather than none.
                min = double.IsFinite(min) ? min : double.IsFinite(max) ? max - 1 : -1;
                max = double.IsFinite(max) ? max : min + 1;
            }

            double span = max * 0.5 - min * 0.5;
            span += span;
            // An axis must span far more than the resolution of its numbers (1e-9 of them), or its ticks and the
            // flight's points would collapse onto each other: a flight 1e12 m from the origin that moves 1 mm.
            double magnitude = Math.Max(Math.Abs(min), Math.Abs(max));
            if (!(span > 1e-6) || !(span > 1e-9 * magnitude))
            {
                span = Math.Max(1, Math.Abs(max));
                min = Math.Max(-double.MaxValue, min - 0.5 * span);
                max = Math.Min(double.MaxValue, max + 0.5 * span);
                return;
            }

            min = Math.Max(-double.MaxValue, min - 0.05 * span);
            max = Math.Min(double.MaxValue, max + 0.08 * span);
        }

        /// <summary>Most ticks drawn on one axis (a guard: the tick spacing gives about 8).</summary>
        internal const int MaxTicksPerAxis = 32;

        private static IEnumerable<double> Ticks(double min, double max)
        {
            double raw = (max * 0.5 - min * 0.5) / 4; // (max - min) / 8, without overflow
            if (!(raw > 0) || !double.IsFinite(raw))
            {
                yield break;
            }

            double magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
            double step = new[] { 1.0, 2.0, 5.0, 10.0 }.Select(m => m * magnitude).FirstOrDefault(s => s >= raw);
            if (!(step > 0) || !double.IsFinite(step))
            {
                yield break;
            }

            // Ticks by index (k step), never by adding steps: a sum can stall where a step is below a double's resolution.
            double first = Math.Ceiling(min / step);
            for (int i = 0; i < MaxTicksPerAxis; i++)
            {
                double t = (first + i) * step;
                // Finite too: near double.MaxValue, max + 1e-9 step rounds to infinity and so would let every tick past
                // the largest double through, each an "Infinity" label (an axis from -1.7e308 to 1.7e308 drew 25 of them).
                if (!(t <= max + 1e-9 * step) || !double.IsFinite(t))
                {
                    yield break;
                }

                yield return Math.Abs(t) < 1e-9 * step ? 0 : Math.Round(t, 10);
            }
        }

        private static string F(double value) => Math.Round(value, 2).ToString("0.##", CultureInfo.InvariantCulture);

        // Tick labels: as before for everyday numbers, in exponent form from 1e7 on (1e300 is not 301 digits).
        private static string Label(double value) =>
            Math.Abs(value) >= 1e7 ? value.ToString("0.###e0", CultureInfo.InvariantCulture) : F(value);

        // XML 1.0 allows tab, newline, carriage return and U+0020 on, except lone surrogates, U+FFFE and U+FFFF:
        // anything else in a name (a control character, U+0000) is written as U+FFFD so the SVG stays well-formed.
        internal static string Escape(string text)
        {
            var escaped = new StringBuilder(text.Length);
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (char.IsHighSurrogate(c) && i + 1 < text.Length && char.IsLowSurrogate(text[i + 1]))
                {
                    escaped.Append(c).Append(text[++i]);
                    continue;
                }

                bool allowed = c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c <= 0xFFFD && !char.IsSurrogate(c));
                escaped.Append(c switch
                {
                    '&' => "&amp;",
                    '<' => "&lt;",
                    '>' => "&gt;",
                    '"' => "&quot;",
                    _ => allowed ? c.ToString() : "\uFFFD",
                });
            }

            return escaped.ToString();
        }
    }
}
