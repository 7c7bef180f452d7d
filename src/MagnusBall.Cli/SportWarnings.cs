using System.Collections.Generic;
using MagnusBall.Presets;
using MagnusBall.Shots;

namespace MagnusBall.Cli
{
    /// <summary>
    /// The unit-mistake guard: with a "preset", a ball or launch outside what any real ball of that sport is or does (a
    /// tennis ball of "mass": 57, grams for kilograms; a spin in rpm typed as rad/s) gets a warning line on stderr, naming
    /// the field; the flight still runs and the exit code stays 0. The limits and their sources are the library's
    /// <see cref="SportLimits"/>.
    /// </summary>
    internal static class SportWarnings
    {
        /// <summary>The warnings for a ball, launch speed (m/s) and spin rate (rad/s), each prefixed by the JSON path of its field.</summary>
        public static IReadOnlyList<string> For(
            SportPreset? preset, Ball ball, double speed, double spinRadiansPerSecond, string ballPath, string speedPath, string spinPath)
        {
            SportLimits? limits = preset is null ? null : SportLimits.For(preset);
            if (limits is null || !double.IsFinite(speed) || !double.IsFinite(spinRadiansPerSecond))
            {
                return System.Array.Empty<string>();
            }

            var lines = new List<string>();
            foreach (string warning in limits.Check(ball.Mass, ball.Radius, speed, Spin.ToRpm(spinRadiansPerSecond)))
            {
                string path = warning.StartsWith("mass", System.StringComparison.Ordinal) ? ballPath + ".mass"
                    : warning.StartsWith("radius", System.StringComparison.Ordinal) ? ballPath + ".radius"
                    : warning.StartsWith("speed", System.StringComparison.Ordinal) ? speedPath
                    : spinPath;
                lines.Add($"{path}: {warning}");
            }

            return lines;
        }
    }
}
