using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using MagnusBall.Flight;

namespace MagnusBall.Samples.TennisScene.Headless
{
    /// <summary>
    /// Draws the court and the shots as an SVG: a side view (x downrange, y up) above a top view (x
    /// downrange, z up the page = the hitter's left), both at the same scale in metres.
    /// </summary>
    internal static class SvgPicture
    {
        private const double Scale = 30;          // px per metre
        private const double XMin = -14.5, XMax = 24.5;
        private const double SideYMin = -0.3;
        private static double SideYMax = 6.5; // raised to fit a ball the net cord pops up (Draw)
        private const double TopZMax = 7.2;
        private const double Margin = 40;

        private static readonly string[] Colours = { "#d62728", "#ff7f0e", "#1f77b4", "#9467bd", "#2ca02c", "#8c564b", "#e377c2", "#17becf" };

        public static string Draw(IReadOnlyList<ShotReport> reports, IReadOnlyList<Vector3d[]> paths, string subtitle)
        {
            SideYMax = 6.5;
            foreach (Vector3d[] path in paths)
            {
                foreach (Vector3d p in path)
                {
                    SideYMax = Math.Max(SideYMax, Math.Ceiling(p.Y + 0.5));
                }
            }

            double width = (XMax - XMin) * Scale + 2 * Margin;
            double sideHeight = (SideYMax - SideYMin) * Scale;
            double topHeight = 2 * TopZMax * Scale;
            double sideTop = Margin + 20;
            double topTop = sideTop + sideHeight + 50;
            double legendTop = topTop + topHeight + 30;
            double height = legendTop + 22 * reports.Count + 20;

            var svg = new StringBuilder();
            svg.AppendLine(F("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:F0}\" height=\"{1:F0}\" viewBox=\"0 0 {0:F0} {1:F0}\" font-family=\"sans-serif\" font-size=\"13\">", width, height));
            svg.AppendLine(F("<rect width=\"{0:F0}\" height=\"{1:F0}\" fill=\"white\"/>", width, height));
            svg.AppendLine(F("<text x=\"{0:F0}\" y=\"22\" font-size=\"16\" font-weight=\"bold\">MagnusBall tennis scene: side view (x, y) and top view (x, z), same scale, metres</text>", Margin));
            svg.AppendLine(F("<text x=\"{0:F0}\" y=\"40\" fill=\"#555\">{1}. Dot: first bounce (X: out); square: second bounce; diamond: the ball touched the net (its cord, mesh or a post).</text>", Margin, Escape(subtitle)));

            svg.AppendLine(F("<defs><clipPath id=\"side\"><rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"{2:F1}\" height=\"{3:F1}\"/></clipPath>" +
                "<clipPath id=\"top\"><rect x=\"{0:F1}\" y=\"{4:F1}\" width=\"{2:F1}\" height=\"{5:F1}\"/></clipPath></defs>",
                Margin, sideTop, (XMax - XMin) * Scale, sideHeight, topTop, topHeight));

            // ----- Side view -----
            Func<double, double> sx = x => Margin + (x - XMin) * Scale;
            Func<double, double> sy = y => sideTop + (SideYMax - y) * Scale;
            svg.AppendLine(F("<text x=\"{0:F0}\" y=\"{1:F0}\" font-weight=\"bold\">side view</text>", Margin, sideTop - 4));
            svg.AppendLine(F("<rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"{2:F1}\" height=\"{3:F1}\" fill=\"#f4f8f4\" stroke=\"#ccc\"/>", sx(XMin), sy(SideYMax), (XMax - XMin) * Scale, sideHeight));
            for (int metre = 1; metre <= (int)SideYMax; metre++)
            {
                svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{2:F1}\" y2=\"{1:F1}\" stroke=\"#e2e8e2\"/>", sx(XMin), sy(metre), sx(XMax)));
                svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" fill=\"#888\" font-size=\"11\">{2} m</text>", sx(XMin) + 3, sy(metre) - 2, metre));
            }

            // Court surface from baseline to baseline, the net (0.914 m at the centre strap, posts 1.07 m), baselines and service lines as ticks.
            svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{2:F1}\" y2=\"{1:F1}\" stroke=\"#3a7d44\" stroke-width=\"4\"/>", sx(-TennisCourt.HalfLength), sy(0), sx(TennisCourt.HalfLength)));
            svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{0:F1}\" y2=\"{2:F1}\" stroke=\"#999\" stroke-width=\"3\"/>", sx(0), sy(0), sy(TennisCourt.NetHeightAtPosts)));
            svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{0:F1}\" y2=\"{2:F1}\" stroke=\"#222\" stroke-width=\"3\"/>", sx(0), sy(0), sy(TennisCourt.NetHeightAtCentre)));
            svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" font-size=\"11\">net 0.914 m (posts 1.07 m)</text>", sx(0) + 4, sy(TennisCourt.NetHeightAtPosts) - 4));
            foreach (double x in new[] { -TennisCourt.HalfLength, -TennisCourt.ServiceLineFromNet, TennisCourt.ServiceLineFromNet, TennisCourt.HalfLength })
            {
                svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{0:F1}\" y2=\"{2:F1}\" stroke=\"#3a7d44\" stroke-width=\"1.5\"/>", sx(x), sy(0) - 6, sy(0) + 6));
            }

            svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" font-size=\"11\" fill=\"#3a7d44\">baseline</text>", sx(-TennisCourt.HalfLength) - 20, sy(0) + 18));
            svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" font-size=\"11\" fill=\"#3a7d44\">service line</text>", sx(TennisCourt.ServiceLineFromNet) - 30, sy(0) + 18));
            svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" font-size=\"11\" fill=\"#3a7d44\">baseline</text>", sx(TennisCourt.HalfLength) - 20, sy(0) + 18));

            for (int i = 0; i < reports.Count; i++)
            {
                string colour = Colours[i % Colours.Length];
                svg.AppendLine(Polyline(paths[i], p => sx(p.X), p => sy(p.Y), colour, "side"));
                NetMarker(svg, reports[i], p => sx(p.X), p => sy(p.Y), colour);
                Vector3d? second = reports[i].SecondBounce;
                Marker(svg, reports[i], sx(reports[i].Landing.X), sy(0), colour, second.HasValue ? sx(second.Value.X) : (double?)null, sy(0));
            }

            // ----- Top view -----
            Func<double, double> tz = z => topTop + (TopZMax - z) * Scale;
            svg.AppendLine(F("<text x=\"{0:F0}\" y=\"{1:F0}\" font-weight=\"bold\">top view (up the page = the hitter's left, +z)</text>", Margin, topTop - 4));
            svg.AppendLine(F("<rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"{2:F1}\" height=\"{3:F1}\" fill=\"#f4f8f4\" stroke=\"#ccc\"/>", sx(XMin), tz(TopZMax), (XMax - XMin) * Scale, topHeight));
            svg.AppendLine(F("<rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"{2:F1}\" height=\"{3:F1}\" fill=\"#4f8a5b\"/>", sx(-TennisCourt.HalfLength), tz(TennisCourt.HalfDoublesWidth), TennisCourt.Length * Scale, TennisCourt.DoublesWidth * Scale));
            foreach (CourtLine line in TennisCourt.Lines())
            {
                svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{2:F1}\" y2=\"{3:F1}\" stroke=\"white\" stroke-width=\"{4:F1}\" stroke-linecap=\"square\"/>",
                    sx(line.Start.X), tz(line.Start.Z), sx(line.End.X), tz(line.End.Z), TennisCourt.LineWidth * Scale));
            }

            svg.AppendLine(F("<line x1=\"{0:F1}\" y1=\"{1:F1}\" x2=\"{0:F1}\" y2=\"{2:F1}\" stroke=\"#222\" stroke-width=\"3\"/>", sx(0), tz(-TennisCourt.PostOffset), tz(TennisCourt.PostOffset)));
            svg.AppendLine(F("<circle cx=\"{0:F1}\" cy=\"{1:F1}\" r=\"4\" fill=\"#222\"/><circle cx=\"{0:F1}\" cy=\"{2:F1}\" r=\"4\" fill=\"#222\"/>", sx(0), tz(-TennisCourt.PostOffset), tz(TennisCourt.PostOffset)));
            svg.AppendLine(F("<text x=\"{0:F1}\" y=\"{1:F1}\" font-size=\"11\">net</text>", sx(0) + 4, tz(TennisCourt.PostOffset) - 6));

            for (int i = 0; i < reports.Count; i++)
            {
                string colour = Colours[i % Colours.Length];
                svg.AppendLine(Polyline(paths[i], p => sx(p.X), p => tz(p.Z), colour, "top"));
                NetMarker(svg, reports[i], p => sx(p.X), p => tz(p.Z), colour);
                Vector3d? second = reports[i].SecondBounce;
                Marker(svg, reports[i], sx(reports[i].Landing.X), tz(reports[i].Landing.Z), colour,
                    second.HasValue ? sx(second.Value.X) : (double?)null, second.HasValue ? tz(second.Value.Z) : (double?)null);
            }

            // ----- Legend -----
            for (int i = 0; i < reports.Count; i++)
            {
                ShotReport r = reports[i];
                double y = legendTop + 22 * i;
                string colour = Colours[i % Colours.Length];
                svg.AppendLine(F("<line x1=\"{0:F0}\" y1=\"{1:F1}\" x2=\"{2:F0}\" y2=\"{1:F1}\" stroke=\"{3}\" stroke-width=\"3\"/>", Margin, y - 4, Margin + 30, colour));
                string landing = r.Landed
                    ? F("bounces at ({0:F2}, {1:F2}) m, {2}; leaves at {3:F1} m/s, {4:F1} deg", r.Landing.X, r.Landing.Z,
                        r.IsLet ? "a LET (clipped the cord, in the box)" : r.IsIn ? "in" : r.ClearedNet ? "OUT" : "NET",
                        r.SpeedAfterBounce, r.ReboundAngleDegrees)
                    : "no landing";
                string clearance = r.NetContact.HasValue
                    ? (ShotSimulation.IsCord(r.NetContact.Value.ShapeId) ? "clips the net cord" : "hits the net")
                    : r.NetClearance.HasValue ? F("net +{0:F2} m", r.NetClearance.Value) : "no net";
                svg.AppendLine(F("<text x=\"{0:F0}\" y=\"{1:F1}\">{2}: {3:F0} m/s at {4:F1} deg, topspin {5:F0} rpm, sidespin {6:F0} rpm; {7}; {8}</text>",
                    Margin + 40, y, Escape(r.Shot.Name), r.Shot.Speed, r.Shot.ElevationDegrees, r.Shot.TopspinRpm, r.Shot.SidespinRpm, clearance, landing, r.ApexHeight, r.TimeOfFlight));
            }

            svg.AppendLine("</svg>");
            return svg.ToString();
        }

        private static void Marker(StringBuilder svg, ShotReport report, double x, double y, string colour, double? secondX = null, double? secondY = null)
        {
            if (!report.Landed)
            {
                return;
            }

            if (report.SecondBounce.HasValue && secondX.HasValue && secondY.HasValue)
            {
                svg.AppendLine(F("<rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"{2}\" stroke-width=\"1.5\"/>", secondX.Value - 3.5, secondY.Value - 3.5, colour));
            }

            if (report.IsIn)
            {
                svg.AppendLine(F("<circle cx=\"{0:F1}\" cy=\"{1:F1}\" r=\"5\" fill=\"{2}\" stroke=\"white\" stroke-width=\"1.5\"/>", x, y, colour));
            }
            else
            {
                svg.AppendLine(F("<path d=\"M{0:F1},{1:F1} l10,10 m0,-10 l-10,10\" stroke=\"{2}\" stroke-width=\"3\"/>", x - 5, y - 5, colour));
            }
        }

        // A diamond where the ball touched the net.
        private static void NetMarker(StringBuilder svg, ShotReport report, Func<Vector3d, double> x, Func<Vector3d, double> y, string colour)
        {
            if (report.NetContact is FlightEvent contact)
            {
                double cx = x(contact.Position), cy = y(contact.Position);
                svg.AppendLine(F("<polygon points=\"{0:F1},{1:F1} {2:F1},{3:F1} {0:F1},{4:F1} {5:F1},{3:F1}\" fill=\"white\" stroke=\"{6}\" stroke-width=\"2\"/>",
                    cx, cy - 6, cx + 6, cy, cy + 6, cx - 6, colour));
            }
        }

        private static string Polyline(Vector3d[] points, Func<Vector3d, double> x, Func<Vector3d, double> y, string colour, string clip)
        {
            var text = new StringBuilder();
            text.Append("<polyline clip-path=\"url(#").Append(clip).Append(")\" fill=\"none\" stroke=\"").Append(colour).Append("\" stroke-width=\"2\" points=\"");
            for (int i = 0; i < points.Length; i++)
            {
                // Every 4th fixed state and the last: ~60 points a second are plenty at this scale.
                if (i % 4 == 0 || i == points.Length - 1 || Kink(points, i))
                {
                    text.Append(F("{0:F1},{1:F1} ", x(points[i]), y(points[i])));
                }
            }

            return text.Append("\"/>").ToString();
        }

        // A bounce or a touch of the net: the path turns there, so the point is drawn.
        private static bool Kink(Vector3d[] points, int i)
        {
            if (i == 0 || i == points.Length - 1)
            {
                return false;
            }

            Vector3d a = points[i] - points[i - 1], b = points[i + 1] - points[i];
            return Vector3d.Dot(a, b) < 0.95 * a.Length * b.Length;
        }

        private static string Escape(string text) => text.Replace("&", "&amp;").Replace("<", "&lt;").Replace(">", "&gt;");

        private static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
