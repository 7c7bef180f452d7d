using System;
using System.IO;
using System.Text;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// Writes docs/figures/racket-launch-vs-swing.svg: launch angle and topspin of a tennis ball against the racket's
    /// path angle, for three face tilts (RacketSwing on the impact law). Not a test: run it by name (it is [Explicit]):
    /// <c>dotnet test tests/MagnusBall.Tests --filter Name=WriteLaunchVersusSwingFigure</c>. The SVG helpers are
    /// BounceFigure's.
    /// </summary>
    [TestFixture]
    [Explicit("Figure generator for docs/impacts.md; run by name.")]
    public class SwingFigure
    {
        private const double MinPath = -10, MaxPath = 60;
        private const double PanelWidth = 300, PanelHeight = 300, Top = 50;
        private static readonly double[] PanelLeft = { 70, 460 };

        [Test]
        [Explicit("Figure generator for docs/impacts.md; run by name.")]
        public void WriteLaunchVersusSwingFigure()
        {
            string path = Path.Combine(BounceFigure.RepositoryRoot(), "docs", "figures", "racket-launch-vs-swing.svg");
            var frame = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);
            var incoming = new Vector3d(-14, 0, -1); // a rally ball, 14 m/s toward the hitter
            double[] faces = { -5, 0, 5 };
            string[] colours = { "#d62728", "#1f77b4", "#2ca02c" };
            (string Title, double Min, double Max, double Step)[] panels = { ("launch angle, deg", -10, 30, 5), ("topspin, rpm", -2000, 5000, 1000) };
            var svg = new StringBuilder();
            var table = new StringBuilder("face,path,speed,elevation,topspin_rpm,regime\n");
            svg.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"820\" height=\"420\" font-family=\"sans-serif\" font-size=\"12\">\n");
            svg.Append("<rect width=\"820\" height=\"420\" fill=\"white\"/>\n");
            svg.Append("<text x=\"70\" y=\"22\" font-size=\"14\">Tennis: launch angle and topspin against the racket's path (25 m/s, ACOR 0.45, hand-held; ball in at 14 m/s)</text>\n");
            for (int p = 0; p < panels.Length; p++)
            {
                double left = PanelLeft[p];
                (string title, double min, double max, double step) = panels[p];
                double X(double x) => left + (x - MinPath) / (MaxPath - MinPath) * PanelWidth;
                double Y(double y) => Top + PanelHeight - (Math.Min(Math.Max(y, min), max) - min) / (max - min) * PanelHeight;
                for (double x = MinPath; x <= MaxPath; x += 10)
                {
                    svg.Append(BounceFigure.F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#ddd\"/>\n", X(x), Top, Top + PanelHeight));
                    svg.Append(BounceFigure.F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">{2}</text>\n", X(x), Top + PanelHeight + 16, x));
                }

                for (double y = min; y <= max + 1e-9; y += step)
                {
                    svg.Append(BounceFigure.F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#ddd\"/>\n", left, Y(y), left + PanelWidth));
                    svg.Append(BounceFigure.F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"end\">{2}</text>\n", left - 6, Y(y) + 4, y));
                }

                svg.Append(BounceFigure.F("<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"black\"/>\n", left, Top, PanelWidth, PanelHeight));
                svg.Append(BounceFigure.F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">racket path above horizontal, deg (low to high)</text>\n", left + PanelWidth / 2, Top + PanelHeight + 34));
                svg.Append(BounceFigure.F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">{2}</text>\n", left + PanelWidth / 2, Top - 8, title));
                for (int f = 0; f < faces.Length; f++)
                {
                    var line = new StringBuilder();
                    for (double x = MinPath; x <= MaxPath + 1e-9; x += 1)
                    {
                        SwingLaunch l = new RacketSwing(25, x, faces[f]).Hit(Ball.Tennis, frame, Vector3d.Zero, incoming, Vector3d.Zero);
                        double y = p == 0 ? l.ElevationDegrees : Spin.ToRpm(l.LaunchSpin.Topspin);
                        line.Append(line.Length == 0 ? "M" : " L").Append(BounceFigure.F("{0:F1},{1:F1}", X(x), Y(y)));
                        if (p == 0 && ((int)Math.Round(x)) % 10 == 0)
                        {
                            table.Append(BounceFigure.F("{0},{1},{2:F2},{3:F2},{4:F0},{5}\n", faces[f], x, l.Speed, l.ElevationDegrees, Spin.ToRpm(l.LaunchSpin.Topspin), l.Impact.Regime));
                        }
                    }

                    svg.Append(BounceFigure.F("<path d=\"{0}\" fill=\"none\" stroke=\"{1}\" stroke-width=\"2\"/>\n", line, colours[f]));
                    if (p == 0)
                    {
                        svg.Append(BounceFigure.F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" stroke-width=\"2\"/>\n", left + 10, Top + 16 + 16 * f, left + 40, colours[f]));
                        svg.Append(BounceFigure.F("<text x=\"{0}\" y=\"{1}\">face tilt {2:+0;-0;0} deg</text>\n", left + 46, Top + 20 + 16 * f, faces[f]));
                    }
                }
            }

            svg.Append("</svg>\n");
            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllText(path, svg.ToString());
            TestContext.Out.WriteLine(table.ToString());
            TestContext.Out.WriteLine($"wrote {path}");
        }
    }
}
