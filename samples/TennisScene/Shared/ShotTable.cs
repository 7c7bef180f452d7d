#nullable enable
using System.Collections.Generic;
using System.Globalization;
using System.Text;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>Formats shot reports as a fixed-width text table (invariant culture, SI units).</summary>
    public static class ShotTable
    {
        /// <summary>The table's header line.</summary>
        public static string Header =>
            string.Format(
                CultureInfo.InvariantCulture,
                "{0,-17} {1,5} {2,6} {3,6} {4,6} {5,6} {6,7} {7,15} {8,-4} {9,5} {10,5} {11,6} {12,6}",
                "shot", "v m/s", "elev", "azim", "top", "side", "net cl", "landing x,z m", "in?", "tof s", "apex", "v_bnc", "angle");

        /// <summary>One row for a report.</summary>
        /// <param name="report">The report.</param>
        public static string Row(ShotReport report)
        {
            TennisShot s = report.Shot;
            string clearance = report.NetClearance.HasValue
                ? report.NetClearance.Value.ToString("+0.00;-0.00", CultureInfo.InvariantCulture)
                : "  none";
            string landing = report.Landed
                ? string.Format(CultureInfo.InvariantCulture, "{0,7:F2},{1,6:F2}", report.Landing.X, report.Landing.Z)
                : "   no landing";
            return string.Format(
                CultureInfo.InvariantCulture,
                "{0,-17} {1,5:F1} {2,6:F1} {3,6:F1} {4,6:F0} {5,6:F0} {6,7} {7,15} {8,-4} {9,5:F2} {10,5:F2} {11,6:F1} {12,6:F1}",
                s.Name, s.Speed, s.ElevationDegrees, s.AzimuthDegrees, s.TopspinRpm, s.SidespinRpm, clearance, landing,
                report.IsIn ? "in" : report.ClearedNet ? "OUT" : "NET", report.TimeOfFlight, report.ApexHeight, report.SpeedAtBounce, report.DescentAngleDegrees);
        }

        /// <summary>The header, a rule, and one row per report.</summary>
        /// <param name="reports">The reports.</param>
        public static string Format(IEnumerable<ShotReport> reports)
        {
            var text = new StringBuilder();
            text.AppendLine(Header);
            text.AppendLine(new string('-', Header.Length));
            foreach (ShotReport report in reports)
            {
                text.AppendLine(Row(report));
            }

            return text.ToString();
        }

        /// <summary>What the columns mean, for a legend under the table.</summary>
        public const string Legend =
            "elev/azim: launch angles, deg (azimuth + toward the hitter's left); top/side: spin, rpm (top < 0: backspin; side > 0 curls left);\n" +
            "net cl: bottom of the ball above the net cord, m; landing: contact point, m (x from the net, z + to the hitter's left);\n" +
            "tof: time to the first bounce, s; apex: highest centre height, m; v_bnc: speed at the bounce, m/s; angle: descent, deg below horizontal.";
    }
}
