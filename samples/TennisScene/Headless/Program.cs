using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;

namespace MagnusBall.Samples.TennisScene.Headless
{
    /// <summary>
    /// The tennis scene without Unity: the same shot definitions, court and measurements as the Unity
    /// scripts (src/MagnusBall/Samples~/TennisScene/Shared, compiled into both), each shot flown through the library's
    /// FixedStepDriver. Prints one table row per shot and writes an SVG of side and top views.
    /// </summary>
    public static class Program
    {
        private static readonly string Usage =
@"usage: dotnet run --project samples/TennisScene/Headless -- [options]

With no shot options, flies the six standard shots (flat serve, kick serve, topspin forehand,
slice backhand, topspin lob, drop shot) and a net-cord let (a serve that clips the tape, the net
being the library's contact shapes, and drops in the box), then the six made by racket swings, each swing
printed next to the launch it produced. Any shot option flies one custom shot instead, starting
from the topspin forehand's values.

shot options (court frame: x from the net toward the far baseline, y up, z to the hitter's left):
  --shot NAME         one of the standard shots by name (e.g. ""kick serve"")
  --speed M/S         launch speed (0.1..120)
  --elevation DEG     launch angle above horizontal (-89.9..89.9)
  --azimuth DEG       launch direction, + toward the hitter's left (-89.9..89.9)
  --topspin RPM       topspin, negative for backspin (-10000..10000)
  --sidespin RPM      sidespin, + curls toward the hitter's left (-10000..10000)
  --height M          hitting height of the ball's centre (0.05..10); a serve is 2.87
  --x M               hitting position along the court (-30..-0.1: the near side; the near baseline is -11.885)
  --z M               hitting position across the court (-10..10)
  --target AREA       court | deuce | ad  (what counts as in)
  --aim X,Z           solve elevation and azimuth (AimSolver) so the ball first touches the court at (X, Z)
  --by-swing          fly the six standard shots as made by racket swings (StandardSwings) instead of by launch
scene options:
  --integrator NAME   " + string.Join(" | ", MagnusBall.Integration.Integrators.Names) + @" (default rk4)
  --step S            fixed step, s (1e-6..0.1; default 1/240)
  --density RHO       air density, kg/m^3 (0..5; default 1.21)
  --thesis-coefficients  constant C_D 0.55 and C_M 0.175 (Agrawal 2023) instead of Stepanek's
  --svg PATH          where to write the picture (default out/tennis-scene.svg)
  --no-svg            do not write the picture
  --help              this text
exit codes: 0 ok, 2 bad options";

        /// <summary>Entry point.</summary>
        /// <param name="args">Command-line options (see --help).</param>
        /// <returns>0 on success, 2 on bad options.</returns>
        public static int Main(string[] args)
        {
            Options options;
            try
            {
                options = Options.Parse(args);
            }
            catch (ArgumentException e)
            {
                Console.Error.WriteLine("error: " + e.Message);
                Console.Error.WriteLine("run with --help for the options.");
                return 2;
            }

            if (options.Help)
            {
                Console.WriteLine(Usage);
                return 0;
            }

            var clock = Stopwatch.StartNew();
            var simulation = new ShotSimulation(options.Settings);
            var reports = new List<ShotReport>();
            var paths = new List<Vector3d[]>();
            var buffer = new Vector3d[(int)(ShotSimulation.MaxFlightSeconds / options.Settings.FixedStep) + 4];
            foreach (TennisShot shot in options.Shots)
            {
                ShotReport report = simulation.Run(shot, buffer);
                reports.Add(report);
                paths.Add(buffer.AsSpan(0, report.PathCount).ToArray());
            }

            Console.WriteLine("MagnusBall tennis scene (headless): " + options.Settings.Describe());
            Console.WriteLine();
            Console.Write(ShotTable.Format(reports));
            Console.WriteLine();
            Console.WriteLine(ShotTable.Legend);

            if (options.Swings.Count > 0)
            {
                // The shots made by swings: the swing next to the launch the library's impact law produced.
                var swingReports = new List<ShotReport>();
                foreach (TennisSwing swing in options.Swings)
                {
                    swingReports.Add(simulation.Run(swing.ToShot(options.Settings.Ball), Span<Vector3d>.Empty));
                }

                Console.WriteLine();
                Console.WriteLine("Made by racket swings (MagnusBall.Contact.Swings.RacketSwing, hand-held racket, ball on the string centre):");
                Console.Write(ShotTable.FormatSwings(swingReports));
                Console.WriteLine();
                Console.WriteLine(ShotTable.SwingLegend);
            }

            if (options.SvgPath != null)
            {
                string path = Path.GetFullPath(options.SvgPath);
                string? directory = Path.GetDirectoryName(path);
                if (!string.IsNullOrEmpty(directory))
                {
                    Directory.CreateDirectory(directory);
                }

                File.WriteAllText(path, SvgPicture.Draw(reports, paths, options.Settings.Describe()));
                Console.WriteLine();
                Console.WriteLine("picture: " + path);
            }

            Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "done in {0:F0} ms", clock.Elapsed.TotalMilliseconds));
            return 0;
        }
    }

    /// <summary>The parsed command line.</summary>
    internal sealed class Options
    {
        public bool Help { get; private set; }

        public SceneSettings Settings { get; private set; } = new SceneSettings();

        public List<TennisShot> Shots { get; } = new List<TennisShot>();

        public List<TennisSwing> Swings { get; } = new List<TennisSwing>();

        public string? SvgPath { get; private set; } = Path.Combine("out", "tennis-scene.svg");

        public static Options Parse(string[] args)
        {
            var options = new Options();
            var values = new Dictionary<string, string>(StringComparer.Ordinal);
            bool thesis = false;
            bool bySwing = false;
            for (int i = 0; i < args.Length; i++)
            {
                string arg = args[i];
                switch (arg)
                {
                    case "--help":
                    case "-h":
                        options.Help = true;
                        continue;
                    case "--no-svg":
                        options.SvgPath = null;
                        continue;
                    case "--thesis-coefficients":
                        thesis = true;
                        continue;
                    case "--by-swing":
                        bySwing = true;
                        continue;
                    case "--shot":
                    case "--speed":
                    case "--elevation":
                    case "--azimuth":
                    case "--topspin":
                    case "--sidespin":
                    case "--height":
                    case "--x":
                    case "--z":
                    case "--target":
                    case "--aim":
                    case "--integrator":
                    case "--step":
                    case "--density":
                    case "--svg":
                        if (i + 1 >= args.Length)
                        {
                            throw new ArgumentException($"{arg} needs a value.");
                        }

                        if (values.ContainsKey(arg))
                        {
                            throw new ArgumentException($"{arg} is given twice.");
                        }

                        values[arg] = args[++i];
                        continue;
                    default:
                        throw new ArgumentException($"unknown option '{arg}'.");
                }
            }

            if (values.TryGetValue("--svg", out string? svg))
            {
                if (string.IsNullOrWhiteSpace(svg))
                {
                    throw new ArgumentException("--svg needs a file path.");
                }

                options.SvgPath = svg;
            }

            double step = Number(values, "--step", 1.0 / 240, min: 1e-6, max: 0.1);
            double density = Number(values, "--density", 1.21, min: 0, max: 5);
            string integrator = values.TryGetValue("--integrator", out string? name) ? name : "rk4";
            try
            {
                MagnusBall.Integration.Integrators.FromName(integrator);
            }
            catch (ArgumentException)
            {
                // The library's message names its own parameter ("name"); this one names the option.
                throw new ArgumentException($"--integrator must be one of: {string.Join(", ", MagnusBall.Integration.Integrators.Names)}; got \"{integrator}\".");
            }

            options.Settings = new SceneSettings(airDensity: density, useStepanekCoefficients: !thesis, integrator: integrator, fixedStep: step);

            TennisShot basis = StandardShots.TopspinForehand;
            if (values.TryGetValue("--shot", out string? shotName))
            {
                TennisShot[] named = [.. StandardShots.All(), StandardShots.NetCordLet];
                basis = Array.Find(named, s => string.Equals(s.Name, shotName, StringComparison.OrdinalIgnoreCase))
                    ?? throw new ArgumentException($"--shot must be one of: {string.Join(", ", Array.ConvertAll(named, s => "\"" + s.Name + "\""))}; got \"{shotName}\".");
            }

            // The options that change the shot itself (the integrator, step, air and picture options do not).
            bool reshaped = false;
            foreach (string key in new[] { "--speed", "--elevation", "--azimuth", "--topspin", "--sidespin", "--height", "--x", "--z", "--target", "--aim" })
            {
                reshaped |= values.ContainsKey(key);
            }

            bool custom = reshaped || values.ContainsKey("--shot");

            if (!custom)
            {
                if (bySwing)
                {
                    // The six standard shots made by racket swings: the main table and the picture show them.
                    foreach (TennisSwing swing in StandardSwings.All())
                    {
                        options.Shots.Add(swing.ToShot(options.Settings.Ball));
                    }
                }
                else
                {
                    // The six, then a serve that clips the net cord and drops in (a let): the net is contact shapes.
                    options.Shots.AddRange(StandardShots.All());
                    options.Shots.Add(StandardShots.NetCordLet);
                }

                options.Swings.AddRange(StandardSwings.All());
                return options;
            }

            if (bySwing)
            {
                throw new ArgumentException("--by-swing flies the six standard shots: give no shot options with it.");
            }

            double speed = Number(values, "--speed", basis.Speed, min: 0.1, max: 120);
            double elevation = Number(values, "--elevation", basis.ElevationDegrees, min: -89.9, max: 89.9);
            double azimuth = Number(values, "--azimuth", basis.AzimuthDegrees, min: -89.9, max: 89.9);
            double topspin = Number(values, "--topspin", basis.TopspinRpm, min: -10000, max: 10000);
            double sidespin = Number(values, "--sidespin", basis.SidespinRpm, min: -10000, max: 10000);
            double height = Number(values, "--height", basis.Start.Y, min: 0.05, max: 10);
            double x = Number(values, "--x", basis.Start.X, min: -30, max: -0.1);
            double z = Number(values, "--z", basis.Start.Z, min: -10, max: 10);
            TargetArea target = basis.Target;
            if (values.TryGetValue("--target", out string? area))
            {
                switch (area)
                {
                    case "court": target = TargetArea.FarSinglesCourt; break;
                    case "deuce": target = TargetArea.FarDeuceServiceBox; break;
                    case "ad": target = TargetArea.FarAdServiceBox; break;
                    default: throw new ArgumentException($"--target must be court, deuce or ad; got \"{area}\".");
                }
            }

            // A standard shot the options change keeps its name, marked with a star; without --shot it is a custom shot.
            string label = !reshaped ? basis.Name : values.ContainsKey("--shot") ? basis.Name + "*" : "custom shot";
            var shot = new TennisShot(label, new Vector3d(x, height, z), speed, elevation, azimuth, topspin, sidespin, target);
            if (values.TryGetValue("--aim", out string? aim))
            {
                string[] parts = aim.Split(',');
                if (parts.Length != 2 ||
                    !double.TryParse(parts[0], NumberStyles.Float, CultureInfo.InvariantCulture, out double aimX) || !double.IsFinite(aimX) ||
                    !double.TryParse(parts[1], NumberStyles.Float, CultureInfo.InvariantCulture, out double aimZ) || !double.IsFinite(aimZ))
                {
                    throw new ArgumentException($"--aim must be two finite numbers X,Z (metres, e.g. 9.5,-2); got \"{aim}\".");
                }

                if (values.ContainsKey("--elevation") || values.ContainsKey("--azimuth"))
                {
                    throw new ArgumentException("--aim solves the elevation and azimuth: give neither --elevation nor --azimuth with it.");
                }

                shot = new ShotSimulation(options.Settings).Aim(shot, aimX, aimZ)
                    ?? throw new ArgumentException(string.Format(
                        CultureInfo.InvariantCulture, "--aim: ({0}, {1}) cannot be reached at {2} m/s with this spin from ({3}, {4}).", aimX, aimZ, speed, x, z));
            }

            options.Shots.Add(shot);
            return options;
        }

        private static double Number(Dictionary<string, string> values, string key, double fallback, double min, double max)
        {
            if (!values.TryGetValue(key, out string? text))
            {
                return fallback;
            }

            if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) || !double.IsFinite(value))
            {
                throw new ArgumentException($"{key} must be a finite number; got \"{text}\".");
            }

            if (value < min || value > max)
            {
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "{0} must be in [{1}, {2}]; got {3}.", key, min, max, value));
            }

            return value;
        }
    }
}
