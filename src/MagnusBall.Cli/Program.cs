using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace MagnusBall.Cli
{
    /// <summary>
    /// The <c>magnusball</c> command-line tool: JSON scenarios in, JSON (or CSV, or an SVG picture) out.
    /// See docs/cli.md. Exit codes: 0 success, 2 bad input or usage, 1 anything else (for example an
    /// output file that cannot be written).
    /// </summary>
    public static class Program
    {
        /// <summary>Exit code for success.</summary>
        public const int Success = 0;

        /// <summary>Exit code for a failure that is not the input's fault (I/O, internal error).</summary>
        public const int Failure = 1;

        /// <summary>Exit code for bad input: a bad scenario/aim file or bad command-line arguments.</summary>
        public const int BadInput = 2;

        internal const string Usage =
            "usage:\n" +
            "  magnusball simulate FILE [--csv] [--samples N] [--svg OUT.svg [--svg-view side|top|both]]\n" +
            "  magnusball aim FILE\n" +
            "  magnusball --help | --version\n" +
            "FILE is a JSON file (\"-\" reads standard input); run magnusball --help for the formats.\n" +
            "  --csv          print the trajectory as CSV instead of the JSON summary\n" +
            "  --samples N    N from 2 to 1000000 states evenly spaced in time (adds \"samples\" to the JSON; CSV rows)\n" +
            "  --svg OUT.svg  also draw side and top views of every scenario to OUT.svg\n" +
            "  --svg-view V   side, top or both (default both); only with --svg\n";

        /// <summary>What --help prints: the usage, then the two file formats, the output and the exit codes.</summary>
        internal const string Help =
            "magnusball: flies spinning balls (gravity, drag, Magnus force) from JSON files.\n\n" +
            Usage +
            "\nsimulate FILE: {\"scenarios\": [ scenario, ... ]}; each scenario (SI units, vectors [x, y, z] in any frame):\n" +
            "  name             string (default \"scenario-<index>\")\n" +
            "  preset           tennis, tennis-free-flight, soccer, baseball, golf, golf-smits-smith, golf-bearman-harvey,\n" +
            "                   golf-linear-2023, table-tennis, basketball: the ball, drag, lift and spin decay (each overridable)\n" +
            "  ball             {\"mass\": kg, \"radius\": m, \"inertiaFactor\": 0.4}; required without a preset\n" +
            "  air              {\"density\": 1.225, \"wind\": [0,0,0]} or {\"temperatureC\", \"pressurePa\", \"relativeHumidity\"}\n" +
            "                   or {\"altitudeM\"}; \"windProfile\" for a logarithmic wind\n" +
            "  gravity          [0, 0, -9.80665] (z up); [0, -9.80665, 0] for a y-up frame\n" +
            "  aero             {\"drag\": {\"model\": none|constant (cd)|stepanek|linear-spin (cd0, k)|goff-carre|nathan},\n" +
            "                    \"lift\": {\"model\": none|constant (cl)|stepanek|linear-spin (k)|goff-carre|nathan|smits-smith-golf|table (points)}}\n" +
            "  spinDecay        {\"model\": none|exponential (tau)|speed-proportional (k)}\n" +
            "  initial          {\"position\": m, \"velocity\": m/s, \"angularVelocity\": rad/s, \"time\": s}; position and velocity required\n" +
            "  integrator       euler, semi-implicit-euler, heun, rk4 (default), dp54, stable-rk4\n" +
            "  step             s (default 1/240); a step beyond the method's stability bound is refused (exit 2)\n" +
            "  maxTime          s (default 10)\n" +
            "  ground           {\"point\", \"normal\"} (default: through the origin, normal up); null for none\n" +
            "  planes           [{\"name\", \"point\", \"normal\", \"bounds\": {\"height\": [min, max], \"width\": [min, max]}}]\n" +
            "  shapes           [{\"type\": box, rectangle, capsule, cylinder, sphere, torus, net-mesh, tennis-net, soccer-goal-frame,\n" +
            "                   basketball-hoop or table-tennis-net, \"id\" (a fixture's \"firstId\") and its geometry: box centre,\n" +
            "                   halfExtents, xAxis, yAxis; rectangle centre, normal, widthDirection, width, height; capsule and\n" +
            "                   cylinder endA, endB, radius; sphere centre, radius; torus centre, axis, ringRadius,\n" +
            "                   tubeRadius; net-mesh as rectangle plus tangentialSpeedKept; primitives restitution (0.7),\n" +
            "                   friction (0.3), mass (fixed; net-mesh too); fixtures\n" +
            "                   tennis-net centreOnGround, across; soccer-goal-frame goalLineCentre, across; basketball-hoop\n" +
            "                   boardFootOnGround, towardCourt; table-tennis-net centreOnSurface, across; each up (the model's)}]\n" +
            "output: {\"results\": [{\"name\", \"landing\": {time, position, velocity} or null, \"apex\", \"crossings\",\n" +
            "  \"contacts\" (with shapes),\n" +
            "  \"steps\", \"derivativeEvaluations\"}]}; with --csv: scenario,time,x,y,z,vx,vy,vz,wx,wy,wz\n" +
            "\naim FILE: {\"aims\": [ aim, ... ]}; each aim has the flight fields above (not initial or planes; shapes are\n" +
            "  obstacles) and\n" +
            "  launch           {\"position\": m, \"spin\": {\"topspin\", \"sidespin\", \"gyro\"} in rad/s}\n" +
            "  find             {\"kind\": minimum-elevation-to-clear (speed, plane {point, normal}, height, azimuthDegrees)\n" +
            "                   | elevation-to-reach (speed, target, azimuthDegrees) | angles-to-reach (speed, target)\n" +
            "                   | speed-to-reach (elevationDegrees, target, azimuthDegrees); the *-to-reach kinds take\n" +
            "                   viaShapeId (a bank shot off that shape)}\n" +
            "  limits           {\"minimumElevationDegrees\": -45, \"maximumElevationDegrees\": 80, \"elevationScanDegrees\": 0.5,\n" +
            "                    \"maximumSpeed\": 100} (optional)\n" +
            "output: {\"results\": [{\"name\", \"status\": solved|unreachable|blocked|work-limit-reached, \"speed\", \"elevationDegrees\",\n" +
            "  \"azimuthDegrees\", \"arrival\", \"miss\", \"simulations\"}]}\n" +
            "\nwarnings: with a preset, a ball's mass or radius, a launch speed or a spin rate outside what real balls of\n" +
            "  that sport reach (a tennis ball of mass 57: grams?) prints one line on stderr per value; the exit code stays 0.\n" +
            "exit codes: 0 success; 2 bad input or usage (one line on stderr naming the field by its JSON path);\n" +
            "  1 anything else (an output file that cannot be written, an internal error).\n";

        /// <summary>The process entry point.</summary>
        /// <param name="args">The command-line arguments.</param>
        public static int Main(string[] args) => Run(args, Console.Out, Console.Error, Console.In);

        /// <summary>Runs the tool in-process: everything it prints goes to the given writers.</summary>
        /// <param name="args">The command-line arguments.</param>
        /// <param name="stdout">Where results go.</param>
        /// <param name="stderr">Where errors go.</param>
        /// <param name="stdin">Read when FILE is "-".</param>
        /// <returns>The exit code: 0 success, 1 failure, 2 bad input or usage.</returns>
        public static int Run(string[] args, TextWriter stdout, TextWriter stderr, TextReader? stdin = null)
        {
            try
            {
                if (args.Length == 0)
                {
                    throw new UsageError("missing command");
                }

                switch (args[0])
                {
                    case "-h":
                    case "--help":
                    case "help":
                        stdout.Write(Help);
                        return Success;
                    case "--version":
                        stdout.WriteLine(typeof(Program).Assembly.GetName().Version?.ToString(3) ?? "0.0.0");
                        return Success;
                    case "simulate":
                        return Simulate(args, stdout, stderr, stdin);
                    case "aim":
                        return Aim(args, stdout, stderr, stdin);
                    default:
                        throw new UsageError($"unknown command '{args[0]}'; expected simulate or aim");
                }
            }
            catch (UsageError e)
            {
                stderr.WriteLine("magnusball: " + e.Message);
                stderr.Write(Usage);
                return BadInput;
            }
            catch (InputError e)
            {
                stderr.WriteLine("magnusball: " + e.Message);
                return BadInput;
            }
            catch (IOException e)
            {
                stderr.WriteLine("magnusball: " + e.Message);
                return Failure;
            }
            catch (UnauthorizedAccessException e)
            {
                stderr.WriteLine("magnusball: " + e.Message);
                return Failure;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                // Never a stack trace: anything else is a bug in the tool, reported as one line with exit code 1.
                stderr.WriteLine($"magnusball: internal error ({e.GetType().Name}): {e.Message.Split('\n')[0]}; please report it with the input file");
                return Failure;
            }
        }

        private static int Simulate(string[] args, TextWriter stdout, TextWriter stderr, TextReader? stdin)
        {
            string? file = null;
            bool csv = false;
            int? samples = null;
            string? svg = null;
            var views = TrajectorySvg.SvgViews.Both;
            bool viewGiven = false;
            var seen = new HashSet<string>(StringComparer.Ordinal);
            for (int i = 1; i < args.Length; i++)
            {
                string a = args[i];
                if (a.StartsWith("--", StringComparison.Ordinal) && !seen.Add(a))
                {
                    // As a repeated JSON field is an error: which one was meant is not for the tool to guess.
                    throw new UsageError($"{a} is given twice; give each option once");
                }

                switch (a)
                {
                    case "--csv":
                        csv = true;
                        break;
                    case "--samples":
                        string n = Value(args, ref i, a);
                        if (!int.TryParse(n, NumberStyles.None, CultureInfo.InvariantCulture, out int count) || count < 2 || count > 1_000_000)
                        {
                            throw new UsageError($"--samples must be a whole number from 2 to 1000000; got '{n}'");
                        }

                        samples = count;
                        break;
                    case "--svg":
                        svg = Value(args, ref i, a);
                        break;
                    case "--svg-view":
                        viewGiven = true;
                        string v = Value(args, ref i, a);
                        views = v switch
                        {
                            "both" => TrajectorySvg.SvgViews.Both,
                            "side" => TrajectorySvg.SvgViews.Side,
                            "top" => TrajectorySvg.SvgViews.Top,
                            _ => throw new UsageError($"--svg-view must be side, top or both; got '{v}'"),
                        };
                        break;
                    default:
                        if (a.StartsWith("--", StringComparison.Ordinal))
                        {
                            throw new UsageError($"unknown option '{a}'");
                        }

                        if (file != null)
                        {
                            throw new UsageError($"simulate takes one FILE; got '{file}' and '{a}'");
                        }

                        file = a;
                        break;
                }
            }

            if (file is null)
            {
                throw new UsageError("simulate needs a scenario FILE");
            }

            if (viewGiven && svg is null)
            {
                throw new UsageError("--svg-view needs --svg OUT.svg (it chooses the views of that picture)");
            }

            IReadOnlyList<Scenario> scenarios = ScenarioReader.Read(ReadInput(file, stdin));
            // Keep only what is printed: every step for plain --csv, else the steps that hold a sample.
            var counts = new List<int>();
            if (samples is int sampleCount)
            {
                counts.Add(sampleCount);
            }

            if (svg != null)
            {
                counts.Add(TrajectorySvg.SamplesPerFlight);
            }

            var recording = new Recording(csv && samples is null, counts);
            var budget = new WorkBudget(ScenarioFlight.EvaluationsPerFileLimit);
            var results = new List<FlightResult>();
            foreach (Scenario scenario in scenarios)
            {
                results.Add(ScenarioFlight.Simulate(scenario, recording, budget));
            }

            if (svg != null)
            {
                try
                {
                    File.WriteAllText(svg, TrajectorySvg.Draw(results, views));
                }
                catch (IOException e)
                {
                    throw new IOException($"cannot write the --svg file '{svg}': {e.Message}", e);
                }
                catch (UnauthorizedAccessException e)
                {
                    throw new UnauthorizedAccessException($"cannot write the --svg file '{svg}': {e.Message}", e);
                }
            }

            stdout.Write(csv ? ResultWriter.Csv(results, samples) : ResultWriter.Json(results, samples));
            // The unit-mistake warnings go out only with a result: an input error stays the one line on stderr.
            foreach (Scenario scenario in scenarios)
            {
                WriteWarnings(stderr, scenario.Warnings);
            }

            return Success;
        }

        private static int Aim(string[] args, TextWriter stdout, TextWriter stderr, TextReader? stdin)
        {
            if (args.Length != 2 || args[1].StartsWith("--", StringComparison.Ordinal) && args[1] != "-")
            {
                throw new UsageError("aim takes exactly one FILE");
            }

            stdout.Write(AimCommand.Run(ReadInput(args[1], stdin), stderr));
            return Success;
        }

        /// <summary>Writes each unit-mistake warning (<see cref="SportWarnings"/>) as one line on stderr.</summary>
        internal static void WriteWarnings(TextWriter stderr, IReadOnlyList<string>? warnings)
        {
            if (warnings is null)
            {
                return;
            }

            foreach (string warning in warnings)
            {
                stderr.WriteLine("magnusball: warning: " + warning);
            }
        }

        private static string Value(string[] args, ref int i, string option)
        {
            if (i + 1 >= args.Length)
            {
                throw new UsageError($"{option} needs a value");
            }

            return args[++i];
        }

        private static string ReadInput(string file, TextReader? stdin)
        {
            if (file == "-")
            {
                return (stdin ?? throw new UsageError("no standard input to read")).ReadToEnd();
            }

            if (!File.Exists(file))
            {
                throw new UsageError($"cannot read '{file}': no such file");
            }

            return File.ReadAllText(file);
        }
    }

    /// <summary>Bad command-line arguments: the CLI prints the message and the usage, and exits with 2.</summary>
    internal sealed class UsageError : Exception
    {
        public UsageError(string message)
            : base(message)
        {
        }
    }
}
