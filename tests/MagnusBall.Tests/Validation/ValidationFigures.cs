using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Json;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Writes the per-sport validation figures of docs/validation.md (docs/figures/validation-*.svg): measured
    /// against simulated, from the same flights the validation tests fly. Not a test: run it by name (it is
    /// [Explicit]): <c>dotnet test tests/MagnusBall.Tests --filter Name=WriteValidationFigures</c>.
    /// </summary>
    [TestFixture]
    [Explicit("Figure generator for docs/validation.md; run by name.")]
    public class ValidationFigures
    {
        [Test]
        [Explicit("Figure generator for docs/validation.md; run by name.")]
        public void WriteValidationFigures()
        {
            string dir = Path.Combine(Path.GetDirectoryName(Path.GetDirectoryName(PublishedCases.Directory())!)!, "docs", "figures");
            Directory.CreateDirectory(dir);

            // Golf: simulated against measured carry, the calibration session and the tour averages.
            var session = GolfValidationTests.FlyAll(SportPresets.Golf, GolfFlights.Session());
            var tour = GolfValidationTests.FlyAll(SportPresets.Golf, GolfFlights.TourAverages());
            var golf = new Plot("golf preset: simulated vs measured carry (TrackMan)", "measured carry, yd", "simulated carry, yd", 60, 320, 60, 320);
            golf.Line(new[] { (60.0, 60.0), (320.0, 320.0) }, "#888", "");
            golf.Line(new[] { (60.0, 60 * 1.08), (320 / 1.08, 320.0) }, "#bbb", "4,3");
            golf.Line(new[] { (60.0, 60 * 0.92), (320.0, 320 * 0.92) }, "#bbb", "4,3");
            golf.Points(session.Select(f => (f.Shot.Carry / GolfFlights.Yard, f.Result.Carry / GolfFlights.Yard)), "#1f77b4", "circle");
            golf.Points(tour.Select(f => (f.Shot.Carry / GolfFlights.Yard, f.Result.Carry / GolfFlights.Yard)), "#d62728", "square");
            golf.Legend(new[] { ("#1f77b4", "session, 24 shots (calibration)"), ("#d62728", "tour averages, 15 (validation)"), ("#bbb", "+-8 %") });
            golf.Save(Path.Combine(dir, "validation-golf.svg"));

            // Golf: simulated against measured landing angle on the tour averages, the preset and the law from measured
            // descent coefficients (GolfNaruoUsgaLaw); the band is issue 43's 1.5 deg target.
            var measured = GolfValidationTests.FlyAll(GolfValidationTests.NaruoUsga(), GolfFlights.TourAverages());
            var landing = new Plot("golf: simulated vs measured landing angle (TrackMan tour averages)", "measured landing angle, deg", "simulated landing angle, deg", 34, 56, 34, 56);
            landing.Line(new[] { (34.0, 34.0), (56.0, 56.0) }, "#888", "");
            landing.Line(new[] { (34.0, 35.5), (54.5, 56.0) }, "#bbb", "4,3");
            landing.Line(new[] { (35.5, 34.0), (56.0, 54.5) }, "#bbb", "4,3");
            landing.Points(tour.Where(f => f.Shot.LandAngle.HasValue).Select(f => (f.Shot.LandAngle!.Value, f.Result.LandAngle)), "#d62728", "square");
            landing.Points(measured.Where(f => f.Shot.LandAngle.HasValue).Select(f => (f.Shot.LandAngle!.Value, f.Result.LandAngle)), "#2ca02c", "circle");
            landing.Legend(new[] { ("#d62728", "golf preset"), ("#2ca02c", "GolfNaruoUsgaLaw (measured coefficients)"), ("#bbb", "+-1.5 deg") });
            landing.Save(Path.Combine(dir, "validation-golf-landing.svg"));

            // Soccer: the curling kick seen from above, measured points and the preset's track.
            JsonElement kick = MenckeFlightTests.Flight("soccer_curling_kick");
            var (_, _, track) = MenckeFlightTests.CurlingKick(SportPresets.Soccer);
            var soccer = new Plot("soccer preset: curling kick seen from above (Mencke et al. 2020, Fig. 10)", "downrange x, m", "sideways z, m", 0, 17, -2, 2.5);
            soccer.Line(new[] { (0.0, 0.0), (16.5, 16.5 * 2.5 / 20) }, "#888", "4,3");
            soccer.Line(track.Select(s => (s.Position.X, s.Position.Z)), "#1f77b4", "");
            soccer.Points(Pairs(kick.GetProperty("measured").GetProperty("track_x_side_m")), "#d62728", "circle");
            soccer.Legend(new[] { ("#d62728", "measured (read from Fig. 10)"), ("#1f77b4", "soccer preset (Teamgeist lift table)"), ("#888", "launch direction") });
            soccer.Save(Path.Combine(dir, "validation-soccer.svg"));

            // Table tennis: the no-spin lob from the side, with the preset and with the law the paper flew it with.
            JsonElement lob = MenckeFlightTests.Flight("table_tennis_lob");
            var (_, _, lobTrack) = MenckeFlightTests.RangeAndApex(MenckeFlightTests.Model(SportPresets.TableTennis), MenckeFlightTests.Launch(lob));
            var (_, _, paperTrack) = MenckeFlightTests.RangeAndApex(MenckeFlightTests.Model(MenckeFlightTests.MenckeTableTennis), MenckeFlightTests.Launch(lob));
            var tt = new Plot("table tennis: no-spin lob (Mencke et al. 2020, Fig. 7)", "downrange x, m", "height y, m", 0, 12, 0, 6);
            tt.Line(lobTrack.Select(s => (s.Position.X, Math.Max(s.Position.Y, 0))), "#1f77b4", "");
            tt.Line(paperTrack.Select(s => (s.Position.X, Math.Max(s.Position.Y, 0))), "#888", "4,3");
            tt.Points(Pairs(lob.GetProperty("measured").GetProperty("track_x_height_m")), "#d62728", "circle");
            tt.Legend(new[] { ("#d62728", "measured (read from Fig. 7)"), ("#1f77b4", "table-tennis preset (Conti et al. 2026)"), ("#888", "the paper's own law (soccer drag, before issue 43)") });
            tt.Save(Path.Combine(dir, "validation-table-tennis.svg"));
            TestContext.Out.WriteLine($"wrote {dir}/validation-{{golf,golf-landing,soccer,table-tennis}}.svg");
        }

        private static IEnumerable<(double, double)> Pairs(JsonElement array) =>
            array.EnumerateArray().Select(p => (p[0].GetDouble(), p[1].GetDouble())).ToList();

        /// <summary>A small SVG x-y plot (the repository's figures are hand-written SVG, as in BounceFigure).</summary>
        private sealed class Plot
        {
            private const double Left = 70, Top = 40, Width = 560, Height = 340;
            private readonly StringBuilder _svg = new StringBuilder();
            private readonly double _x0, _x1, _y0, _y1;

            public Plot(string title, string xLabel, string yLabel, double x0, double x1, double y0, double y1)
            {
                _x0 = x0;
                _x1 = x1;
                _y0 = y0;
                _y1 = y1;
                _svg.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"720\" height=\"440\" font-family=\"sans-serif\" font-size=\"12\">\n");
                _svg.Append("<rect width=\"720\" height=\"440\" fill=\"white\"/>\n");
                _svg.Append(F("<text x=\"{0}\" y=\"22\" font-size=\"14\">{1}</text>\n", Left, title));
                foreach (double x in Ticks(x0, x1))
                {
                    _svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#eee\"/>\n", X(x), Top, Top + Height));
                    _svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">{2}</text>\n", X(x), Top + Height + 16, x));
                }

                foreach (double y in Ticks(y0, y1))
                {
                    _svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#eee\"/>\n", Left, Y(y), Left + Width));
                    _svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"end\">{2}</text>\n", Left - 6, Y(y) + 4, y));
                }

                _svg.Append(F("<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"black\"/>\n", Left, Top, Width, Height));
                _svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">{2}</text>\n", Left + Width / 2, Top + Height + 34, xLabel));
                _svg.Append(F("<text x=\"18\" y=\"{0}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {0})\">{1}</text>\n", Top + Height / 2, yLabel));
            }

            public void Line(IEnumerable<(double X, double Y)> points, string colour, string dash)
            {
                string d = string.Join(" ", points.Select((p, i) => (i == 0 ? "M" : "L") + F("{0:F1},{1:F1}", X(p.X), Y(p.Y))));
                _svg.Append(F("<path d=\"{0}\" fill=\"none\" stroke=\"{1}\" stroke-width=\"2\"{2}/>\n", d, colour, dash.Length > 0 ? F(" stroke-dasharray=\"{0}\"", dash) : ""));
            }

            public void Points(IEnumerable<(double X, double Y)> points, string colour, string shape)
            {
                foreach ((double x, double y) in points)
                {
                    _svg.Append(shape == "square"
                        ? F("<rect x=\"{0:F1}\" y=\"{1:F1}\" width=\"7\" height=\"7\" fill=\"{2}\"/>\n", X(x) - 3.5, Y(y) - 3.5, colour)
                        : F("<circle cx=\"{0:F1}\" cy=\"{1:F1}\" r=\"3.5\" fill=\"{2}\"/>\n", X(x), Y(y), colour));
                }
            }

            public void Legend(IEnumerable<(string Colour, string Text)> entries)
            {
                int i = 0;
                foreach ((string colour, string text) in entries)
                {
                    double y = Top + 18 + 16 * i++;
                    _svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" stroke-width=\"3\"/>\n", Left + 12, y, Left + 36, colour));
                    _svg.Append(F("<text x=\"{0}\" y=\"{1}\">{2}</text>\n", Left + 42, y + 4, text));
                }
            }

            public void Save(string path) => File.WriteAllText(path, _svg + "</svg>\n");

            private static IEnumerable<double> Ticks(double from, double to)
            {
                double span = to - from;
                double step = span > 100 ? 40 : span > 10 ? 2 : span > 4 ? 1 : 0.5;
                for (double v = Math.Ceiling(from / step) * step; v <= to + 1e-9; v += step)
                {
                    yield return Math.Round(v, 6);
                }
            }

            private double X(double x) => Left + (x - _x0) / (_x1 - _x0) * Width;

            private double Y(double y) => Top + Height - (y - _y0) / (_y1 - _y0) * Height;

            private static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
        }
    }
}
