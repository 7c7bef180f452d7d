#nullable enable
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>Formats shot reports as a fixed-width text table (invariant culture, SI units).</summary>
    public static class ShotTable
    {
        private const string Layout =
            "{0,-17} {1,5} {2,5} {3,5} {4,5} {5,5} {6,6} {7,13} {8,-3} {9,5} {10,5} {11,5} {12,5} {13,5} {14,5} {15,6} {16,-5} {17,13}";

        /// <summary>The table's header line.</summary>
        public static string Header =>
            string.Format(
                CultureInfo.InvariantCulture, Layout,
                "shot", "v", "elev", "azim", "top", "side", "net", "landing x,z", "in?", "tof", "apex", "v_in", "a_in", "v_out", "a_out", "w_out", "slip", "2nd bounce");

        /// <summary>The units line under the header.</summary>
        public static string Units =>
            string.Format(
                CultureInfo.InvariantCulture, Layout,
                string.Empty, "m/s", "deg", "deg", "rpm", "rpm", "m", "m", string.Empty, "s", "m", "m/s", "deg", "m/s", "deg", "rpm", string.Empty, "x,z m");

        /// <summary>One row for a report.</summary>
        /// <param name="report">The report.</param>
        public static string Row(ShotReport report)
        {
            TennisShot s = report.Shot;
            string clearance = report.NetContact.HasValue
                ? (ShotSimulation.IsCord(report.NetContact.Value.ShapeId) ? "cord" : "net")
                : report.NetClearance.HasValue
                ? report.NetClearance.Value.ToString("+0.00;-0.00", CultureInfo.InvariantCulture)
                : "none";
            string landing = report.Landed ? Point(report.Landing) : "none";
            string second = report.SecondBounce.HasValue ? Point(report.SecondBounce.Value) : "rests";
            string verdict = report.IsLet ? "LET" : report.IsIn ? "in" : report.ClearedNet ? "OUT" : "NET";
            return string.Format(
                CultureInfo.InvariantCulture, Layout,
                s.Name, F(s.Speed, "0.0"), F(s.ElevationDegrees, "0.0"), F(s.AzimuthDegrees, "0.0"), F(s.TopspinRpm, "0"), F(s.SidespinRpm, "0"),
                clearance, landing, verdict, F(report.TimeOfFlight, "0.00"), F(report.ApexHeight, "0.00"),
                F(report.SpeedAtBounce, "0.0"), F(report.DescentAngleDegrees, "0.0"),
                F(report.SpeedAfterBounce, "0.0"), F(report.ReboundAngleDegrees, "0.0"), F(report.TopspinAfterBounceRpm, "0"),
                report.Landed ? report.BounceRegime.ToString().ToLowerInvariant() : string.Empty, second);
        }

        /// <summary>The header, the units, a rule, and one row per report.</summary>
        /// <param name="reports">The reports.</param>
        public static string Format(IEnumerable<ShotReport> reports)
        {
            var text = new StringBuilder();
            text.AppendLine(Header);
            text.AppendLine(Units);
            text.AppendLine(new string('-', Header.Length));
            foreach (ShotReport report in reports)
            {
                text.AppendLine(Row(report));
            }

            return text.ToString();
        }

        /// <summary>What the columns mean, for a legend under the table.</summary>
        public const string Legend =
            "shot: a name with * is a standard shot changed by the shot options.\n" +
            "v, elev, azim: launch speed and angles (azimuth + toward the hitter's left); top, side: launch spin (top < 0: backspin; side > 0 curls left).\n" +
            "net: bottom of the ball above the net cord (cord: it clipped the tape, net: it hit the mesh or a post); landing: first contact point\n" +
            "(x from the net, z + to the hitter's left); in?: in the target area (service box for serves), NET if it did not clear, LET for a serve\n" +
            "that clipped the cord and dropped in its box; tof: time to the first bounce; apex: highest centre height; v_in, a_in: speed and\n" +
            "descent angle into the first bounce; v_out, a_out, w_out: speed, rebound angle and topspin (rpm, < 0 backspin) out of it; slip: whether\n" +
            "the contact slid throughout or gripped (Cross's bounce model); 2nd bounce: the next contact point.";

        /// <summary>
        /// The swings table: each swing next to the launch it produced and where it landed. Rows start with two spaces
        /// (so they never start with a shot's name, which the main table's rows do).
        /// </summary>
        /// <param name="reports">Reports of shots made by swings (<see cref="TennisShot.Swing"/> set).</param>
        public static string FormatSwings(IEnumerable<ShotReport> reports)
        {
            var text = new StringBuilder();
            text.AppendLine(string.Format(
                CultureInfo.InvariantCulture, SwingLayout, "swing", "racket", "path", "face", "turn", "ACOR", "azim", "->", "v", "elev", "azim", "top", "side", "landing x,z", "in?"));
            text.AppendLine(string.Format(
                CultureInfo.InvariantCulture, SwingLayout, string.Empty, "m/s", "deg", "deg", "deg", string.Empty, "deg", string.Empty, "m/s", "deg", "deg", "rpm", "rpm", "m", string.Empty));
            foreach (ShotReport report in reports)
            {
                TennisShot s = report.Shot;
                TennisSwing? swing = s.Swing;
                if (swing == null)
                {
                    continue;
                }

                RacketSwingView w = new RacketSwingView(swing);
                text.AppendLine(string.Format(
                    CultureInfo.InvariantCulture, SwingLayout, s.Name, F(w.Speed, "0.0"), F(w.Path, "0.0"), F(w.Face, "0.000"), F(w.Turn, "0.0"), F(w.Acor, "0.00"),
                    F(w.Azimuth, "0.000"), "->", F(s.Speed, "0.0"), F(s.ElevationDegrees, "0.0"), F(s.AzimuthDegrees, "0.0"), F(s.TopspinRpm, "0"), F(s.SidespinRpm, "0"),
                    report.Landed ? Point(report.Landing) : "none", report.IsIn ? "in" : report.ClearedNet ? "OUT" : "NET"));
            }

            return text.ToString();
        }

        /// <summary>What the swing table's columns mean.</summary>
        public const string SwingLegend =
            "racket: racket speed at the impact point; path: its elevation (+ low to high); face: the face normal's tilt (+ open); turn: the face's\n" +
            "azimuth from the path; ACOR: apparent COR at the impact point (0.45 string centre); azim: the swing's azimuth, + toward the hitter's right\n" +
            "(the court launch frame's side). The launch columns are the impact law's result (MagnusBall.Contact.Impact), in the main table's units.";

        private const string SwingLayout = "  {0,-16} {1,6} {2,6} {3,7} {4,5} {5,4} {6,7} {7,2} {8,5} {9,5} {10,5} {11,5} {12,5} {13,13} {14,-3}";

        private readonly struct RacketSwingView
        {
            public RacketSwingView(TennisSwing swing)
            {
                Speed = swing.Swing.Speed;
                Path = swing.Swing.PathElevationDegrees;
                Face = swing.Swing.FaceTiltDegrees;
                Turn = swing.Swing.FaceTurnDegrees;
                Acor = swing.Swing.ApparentRestitution;
                Azimuth = swing.Swing.AzimuthDegrees;
            }

            public double Speed { get; }

            public double Path { get; }

            public double Face { get; }

            public double Turn { get; }

            public double Acor { get; }

            public double Azimuth { get; }
        }

        private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

        private static string Point(in Vector3d p) => string.Format(CultureInfo.InvariantCulture, "{0,6:F2},{1,6:F2}", p.X, p.Z);
    }
}
