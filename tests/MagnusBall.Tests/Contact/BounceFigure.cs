using System;
using System.Globalization;
using System.IO;
using System.Text;
using MagnusBall.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// Writes docs/figures/bounce-angle-vs-spin.svg: outgoing angle against incoming spin on the three courts.
    /// Not a test: run it by name (it is [Explicit], so the default run skips it):
    /// <c>dotnet test tests/MagnusBall.Tests --filter Name=WriteAngleVersusSpinFigure</c>.
    /// </summary>
    [TestFixture]
    [Explicit("Figure generator for docs/bounce.md; run by name.")]
    public class BounceFigure
    {
        private const double MinRpm = -4000, MaxRpm = 4000, MinAngle = 0, MaxAngle = 70;
        private const double Left = 70, Top = 40, Width = 560, Height = 340;

        [Test]
        [Explicit("Figure generator for docs/bounce.md; run by name.")]
        public void WriteAngleVersusSpinFigure()
        {
            string path = Path.Combine(RepositoryRoot(), "docs", "figures", "bounce-angle-vs-spin.svg");
            var svg = new StringBuilder();
            var table = new StringBuilder("surface,incoming,rpm,regime,speed_out,angle_out,rpm_out\n");
            svg.Append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"720\" height=\"440\" font-family=\"sans-serif\" font-size=\"12\">\n");
            svg.Append("<rect width=\"720\" height=\"440\" fill=\"white\"/>\n");
            svg.Append(F("<text x=\"{0}\" y=\"22\" font-size=\"14\">Outgoing angle vs incoming spin, tennis ball (R 0.033 m, alpha 0.55), Cross bounce</text>\n", Left));

            // Axes and grid.
            for (double rpm = MinRpm; rpm <= MaxRpm; rpm += 1000)
            {
                double x = X(rpm);
                svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#ddd\"/>\n", x, Top, Top + Height));
                svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">{2}</text>\n", x, Top + Height + 16, rpm));
            }

            for (double a = MinAngle; a <= MaxAngle; a += 10)
            {
                double y = Y(a);
                svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#ddd\"/>\n", Left, y, Left + Width));
                svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"end\">{2}</text>\n", Left - 6, y + 4, a));
            }

            svg.Append(F("<rect x=\"{0}\" y=\"{1}\" width=\"{2}\" height=\"{3}\" fill=\"none\" stroke=\"black\"/>\n", Left, Top, Width, Height));
            svg.Append(F("<text x=\"{0}\" y=\"{1}\" text-anchor=\"middle\">incoming spin, rpm (negative = backspin, positive = topspin)</text>\n",
                Left + Width / 2, Top + Height + 34));
            svg.Append(F("<text x=\"18\" y=\"{0}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {0})\">outgoing angle above the court, deg</text>\n",
                Top + Height / 2));

            string[] colours = { "#d62728", "#b8860b", "#2ca02c" };
            Surface[] courts = Surface.Courts;
            (double Speed, double Angle, string Dash)[] incoming = { (25, 16, ""), (20, 25, "6,4") };
            for (int s = 0; s < courts.Length; s++)
            {
                var model = new CrossBounce(courts[s]);
                foreach ((double speed, double angle, string dash) in incoming)
                {
                    var path1 = new StringBuilder();
                    BounceRegime previous = BounceRegime.None;
                    for (double rpm = MinRpm; rpm <= MaxRpm + 1e-9; rpm += 10)
                    {
                        BounceOutcome o = Court.ZUp.Bounce(model, Ball.Tennis, speed, angle, rpm);
                        double out1 = Court.ZUp.AngleDegrees(o);
                        // Break the line where the regime switches: the model jumps there (see docs/bounce.md).
                        path1.Append(o.Regime != previous ? " M" : " L").Append(F("{0},{1}", X(rpm), Y(Math.Min(Math.Max(out1, MinAngle), MaxAngle))));
                        previous = o.Regime;
                        if (((int)Math.Round(rpm)) % 500 == 0)
                        {
                            table.Append(F("{0},{1} m/s at {2} deg,{3},{4},{5:F2},{6:F1},{7:F0}\n",
                                courts[s].Name, speed, angle, rpm, o.Regime, Court.ZUp.Speed(o), out1, Court.ZUp.TopspinRpm(o)));
                        }
                    }

                    svg.Append(F("<path d=\"{0}\" fill=\"none\" stroke=\"{1}\" stroke-width=\"2\"{2}/>\n",
                        path1.ToString().Trim(), colours[s], dash.Length > 0 ? F(" stroke-dasharray=\"{0}\"", dash) : ""));
                }

                svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" stroke-width=\"2\"/>\n",
                    Left + Width - 150, Top + 18 + 16 * s, Left + Width - 120, colours[s]));
                svg.Append(F("<text x=\"{0}\" y=\"{1}\">{2}</text>\n", Left + Width - 114, Top + 22 + 16 * s, courts[s].Name));
            }

            svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>\n", Left + Width - 150, Top + 74, Left + Width - 120));
            svg.Append(F("<text x=\"{0}\" y=\"{1}\">25 m/s at 16 deg</text>\n", Left + Width - 114, Top + 78));
            svg.Append(F("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\" stroke-dasharray=\"6,4\"/>\n", Left + Width - 150, Top + 92, Left + Width - 120));
            svg.Append(F("<text x=\"{0}\" y=\"{1}\">20 m/s at 25 deg</text>\n", Left + Width - 114, Top + 96));
            svg.Append("</svg>\n");

            Directory.CreateDirectory(Path.GetDirectoryName(path)!);
            File.WriteAllText(path, svg.ToString());
            TestContext.Out.WriteLine(table.ToString());
            TestContext.Out.WriteLine($"wrote {path}");
        }

        private static double X(double rpm) => Left + (rpm - MinRpm) / (MaxRpm - MinRpm) * Width;

        private static double Y(double angle) => Top + Height - (angle - MinAngle) / (MaxAngle - MinAngle) * Height;

        internal static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);

        internal static string RepositoryRoot()
        {
            string? dir = TestContext.CurrentContext.TestDirectory;
            while (dir != null && !File.Exists(Path.Combine(dir, "MagnusBall.sln")))
            {
                dir = Path.GetDirectoryName(dir);
            }

            return dir ?? throw new InvalidOperationException("MagnusBall.sln not found above the test directory");
        }
    }
}
