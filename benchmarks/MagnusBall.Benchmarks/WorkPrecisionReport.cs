using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using MagnusBall.Integration;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Mode "work-precision": landing-point error against cost for every integrator and step on five shots; writes
    /// docs/accuracy-vs-speed.md and docs/figures/accuracy-vs-speed.svg.
    /// </summary>
    internal static class WorkPrecisionReport
    {
        public static readonly double[] Steps = { 1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480, 1.0 / 1000 };
        public static readonly double[] Tolerances = { 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10 };
        private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;
        private const double MaxTime = 30;

        private sealed class Row
        {
            public string Method = "";
            public string Setting = "";
            public double Step;
            public double[] Errors = Array.Empty<double>();
            public long[] Evaluations = Array.Empty<long>();
            public double[] Nanoseconds = Array.Empty<double>();
            public double WorstError => Errors.Max();
            public double TotalNanoseconds => Nanoseconds.Sum();
            public long TotalEvaluations => Evaluations.Sum();
        }

        public static void Run(string docsDirectory)
        {
            var watch = Stopwatch.StartNew();
            Shot[] shots = Shot.All();
            var references = new Vector3d[shots.Length];
            var referenceCheck = new double[shots.Length];
            var referenceEvaluations = new long[shots.Length];
            for (int i = 0; i < shots.Length; i++)
            {
                if (!Flight.TryLandReference(shots[i].Model, shots[i].Launch, MaxTime, 1e-12, out references[i], out referenceEvaluations[i]))
                {
                    throw new InvalidOperationException(shots[i].Name + " did not land");
                }

                Flight.TryLand(shots[i].Model, RungeKutta4.Instance, shots[i].Launch, 1e-5, MaxTime, out Vector3d rk4, out _);
                referenceCheck[i] = Vector3d.Distance(rk4, references[i]);
            }

            // Two passes: the first lets tiered compilation reach its optimised code; only the second is reported.
            var rows = new List<Row>();
            for (int pass = 0; pass < 2; pass++)
            {
                rows.Clear();
                foreach (IIntegrator integrator in Scenarios.FixedStepIntegrators)
                {
                    foreach (double step in Steps)
                    {
                        var row = new Row { Method = integrator.Name, Setting = ExtremesReport.StepName(step) + " s", Step = step };
                        Measure(row, shots, references, (Shot shot, out Vector3d landing, out long evaluations) =>
                            Flight.TryLand(shot.Model, integrator, shot.Launch, step, MaxTime, out landing, out evaluations));
                        rows.Add(row);
                    }
                }

                foreach (double tolerance in Tolerances)
                {
                    var row = new Row { Method = "dp54-adaptive", Setting = "tol " + tolerance.ToString("0E0", Inv) };
                    Measure(row, shots, references, (Shot shot, out Vector3d landing, out long evaluations) =>
                        Flight.TryLandReference(shot.Model, shot.Launch, MaxTime, tolerance, out landing, out evaluations));
                    rows.Add(row);
                }

                System.Threading.Thread.Sleep(pass == 0 ? 500 : 0);
            }

            string markdown = Markdown(shots, references, referenceCheck, referenceEvaluations, rows, watch.Elapsed.TotalSeconds);
            Directory.CreateDirectory(Path.Combine(docsDirectory, "figures"));
            File.WriteAllText(Path.Combine(docsDirectory, "accuracy-vs-speed.md"), markdown);
            File.WriteAllText(Path.Combine(docsDirectory, "figures", "accuracy-vs-speed.svg"), Svg(rows, shots));
            Console.WriteLine(markdown);
        }

        private delegate bool Land(Shot shot, out Vector3d landing, out long evaluations);

        private static void Measure(Row row, Shot[] shots, Vector3d[] references, Land land)
        {
            row.Errors = new double[shots.Length];
            row.Evaluations = new long[shots.Length];
            row.Nanoseconds = new double[shots.Length];
            for (int i = 0; i < shots.Length; i++)
            {
                if (!land(shots[i], out Vector3d landing, out long evaluations))
                {
                    row.Errors[i] = double.PositiveInfinity;
                    continue;
                }

                row.Errors[i] = Vector3d.Distance(landing, references[i]);
                row.Evaluations[i] = evaluations;

                // Time: the fastest of several repetitions (the machine is shared; the minimum is the least disturbed).
                int repetitions = Math.Max(3, (int)Math.Min(200, 2_000_000 / Math.Max(1, evaluations)));
                double best = double.PositiveInfinity;
                for (int r = 0; r < repetitions; r++)
                {
                    long start = Stopwatch.GetTimestamp();
                    land(shots[i], out _, out _);
                    long ticks = Stopwatch.GetTimestamp() - start;
                    best = Math.Min(best, ticks * 1e9 / Stopwatch.Frequency);
                }

                row.Nanoseconds[i] = best;
            }
        }

        private static string E(double v) => double.IsPositiveInfinity(v) ? "no landing" : v.ToString("0.0E0", Inv);

        private static string Us(double ns) => (ns / 1000).ToString(ns < 10_000 ? "F2" : ns < 100_000 ? "F1" : "F0", Inv);

        private static string Markdown(Shot[] shots, Vector3d[] references, double[] check, long[] referenceEvaluations, List<Row> rows, double seconds)
        {
            var sb = new StringBuilder();
            sb.AppendLine("# Accuracy against speed");
            sb.AppendLine();
            sb.AppendLine("Generated by `dotnet run -c Release --project benchmarks/MagnusBall.Benchmarks -- work-precision` (do not edit by hand;");
            sb.AppendLine($"run time {seconds:F0} s). Machine: {Environment.ProcessorCount} cores, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}, .NET {Environment.Version}; the machine was shared with other jobs, so times are the fastest of repeated runs and can be off by tens of per cent; evaluation counts are exact.");
            sb.AppendLine();
            sb.AppendLine("Each shot is flown with a fixed step from launch until the ball's centre comes down through height 0; the landing is");
            sb.AppendLine("located on the cubic Hermite of the step in which it lands (the queries' `HermiteSegment.TryFindCrossing`, built from");
            sb.AppendLine("the step's end states and end derivatives, so no extra evaluation). The error is the");
            sb.AppendLine("distance from that landing point to the reference landing point. Cost is counted in derivative evaluations (the");
            sb.AppendLine("honest unit across methods) and in microseconds for the whole flight, single-threaded.");
            sb.AppendLine();
            sb.AppendLine("## Shots and reference");
            sb.AppendLine();
            sb.AppendLine("Reference: adaptive Dormand-Prince 5(4) at rtol = atol = 1e-12, landing located by bisection on its own fourth-order dense output. Check: RK4 at a fixed 1e-5 s step with the Hermite landing.");
            sb.AppendLine();
            sb.AppendLine("| shot | model | reference landing (m) | DP54 evaluations | distance DP54 (1e-12) to RK4 (1e-5 s) (m) |");
            sb.AppendLine("|---|---|---|---|---|");
            for (int i = 0; i < shots.Length; i++)
            {
                Vector3d r = references[i];
                sb.AppendLine($"| {shots[i].Name} | {ModelName(shots[i].Model)} | ({r.X.ToString("F3", Inv)}, {r.Y.ToString("F3", Inv)}, {r.Z.ToString("0.0E0", Inv)}) | {referenceEvaluations[i]} | {check[i].ToString("0.0E0", Inv)} |");
            }

            sb.AppendLine();
            sb.AppendLine("Errors below about 1e-10 m are at the reference's own accuracy and mean \"as good as the reference\".");
            sb.AppendLine();
            sb.AppendLine("## Chart");
            sb.AppendLine();
            sb.AppendLine("![landing error against cost](figures/accuracy-vs-speed.svg)");
            sb.AppendLine();
            sb.AppendLine("Worst landing error over the five shots against the summed cost of flying all five, log-log, one line per method (points: steps 1/30 ... 1/1000 s; for dp54-adaptive: tolerances 1e-3 ... 1e-10).");
            sb.AppendLine();
            sb.AppendLine("## Table");
            sb.AppendLine();
            sb.Append("Landing error (m) per shot; cost summed over the five shots.").AppendLine();
            sb.AppendLine();
            sb.Append("| method | step |");
            foreach (Shot s in shots)
            {
                sb.Append(' ').Append(s.Name).Append(" |");
            }

            sb.AppendLine(" worst | evaluations | time (us) |");
            sb.Append("|---|---|").Append(string.Concat(Enumerable.Repeat("---|", shots.Length + 3))).AppendLine();
            foreach (Row row in rows)
            {
                sb.Append($"| {row.Method} | {row.Setting} |");
                foreach (double e in row.Errors)
                {
                    sb.Append(' ').Append(E(e)).Append(" |");
                }

                sb.AppendLine($" {E(row.WorstError)} | {row.TotalEvaluations} | {Us(row.TotalNanoseconds)} |");
            }

            sb.AppendLine();
            sb.AppendLine("## Recommendation");
            sb.AppendLine();
            sb.AppendLine("For each error budget: the cheapest setting (fewest derivative evaluations over the five shots, exact and machine-independent; time breaks ties) whose worst landing error over the five shots is within the budget, and the cheapest fixed-step one (what a game's fixed step can use).");
            sb.AppendLine();
            sb.AppendLine("| budget | cheapest | worst error (m) | time (us, 5 shots) | evaluations | cheapest fixed step | worst error (m) | time (us) | evaluations |");
            sb.AppendLine("|---|---|---|---|---|---|---|---|---|");
            foreach ((string name, double budget) in new[] { ("1 m", 1.0), ("1 cm", 1e-2), ("1 mm", 1e-3), ("1 um", 1e-6) })
            {
                Row? any = rows.Where(r => r.WorstError <= budget).OrderBy(r => r.TotalEvaluations).ThenBy(r => r.TotalNanoseconds).FirstOrDefault();
                Row? fixedStep = rows.Where(r => r.Step > 0 && r.WorstError <= budget).OrderBy(r => r.TotalEvaluations).ThenBy(r => r.TotalNanoseconds).FirstOrDefault();
                sb.Append($"| {name} | ");
                sb.Append(any == null ? "none | - | - | - | " : $"{any.Method} {any.Setting} | {E(any.WorstError)} | {Us(any.TotalNanoseconds)} | {any.TotalEvaluations} | ");
                sb.AppendLine(fixedStep == null ? "none | - | - | - |" : $"{fixedStep.Method} {fixedStep.Setting} | {E(fixedStep.WorstError)} | {Us(fixedStep.TotalNanoseconds)} | {fixedStep.TotalEvaluations} |");
            }

            sb.AppendLine();
            Row rk4 = rows.First(r => r.Method == "rk4" && r.Step == 1.0 / 60);
            Row euler = rows.First(r => r.Method == "euler" && r.Step == 1.0 / 60);
            sb.AppendLine($"Headline (40 m/s tennis topspin drive, Hermite landing): RK4 at 1/60 s lands {E(rk4.Errors[0])} m from the reference; explicit Euler at 1/60 s, {E(euler.Errors[0])} m.");
            return sb.ToString();
        }

        private static string ModelName(FlightModel model) =>
            $"{model.Ball.Mass * 1000:G3} g, r {model.Ball.Radius * 1000:G3} mm; {model.Drag}; {model.Lift}; {model.SpinDecay}";

        private static string Svg(List<Row> rows, Shot[] shots)
        {
            const double width = 760, height = 520, left = 80, right = 190, top = 30, bottom = 60;
            var series = rows.GroupBy(r => r.Method).ToList();
            double minX = Math.Log10(rows.Min(r => r.TotalNanoseconds / 1000)), maxX = Math.Log10(rows.Max(r => r.TotalNanoseconds / 1000));
            double floor = 1e-12;
            double minY = Math.Log10(Math.Max(floor, rows.Where(r => !double.IsInfinity(r.WorstError)).Min(r => r.WorstError)));
            double maxY = Math.Log10(rows.Where(r => !double.IsInfinity(r.WorstError)).Max(r => r.WorstError));
            minX = Math.Floor(minX);
            maxX = Math.Ceiling(maxX);
            minY = Math.Floor(minY);
            maxY = Math.Ceiling(maxY);
            double X(double us) => left + (Math.Log10(us) - minX) / (maxX - minX) * (width - left - right);
            double Y(double e) => top + (maxY - Math.Log10(Math.Max(floor, e))) / (maxY - minY) * (height - top - bottom);
            string[] colours = { "#d62728", "#ff7f0e", "#2ca02c", "#1f77b4", "#9467bd", "#8c564b" };
            var sb = new StringBuilder();
            sb.AppendLine($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" font-family=\"sans-serif\" font-size=\"12\">");
            sb.AppendLine($"<rect width=\"{width}\" height=\"{height}\" fill=\"white\"/>");
            for (double d = minX; d <= maxX; d++)
            {
                double x = X(Math.Pow(10, d));
                sb.AppendLine($"<line x1=\"{F(x)}\" y1=\"{top}\" x2=\"{F(x)}\" y2=\"{height - bottom}\" stroke=\"#ddd\"/>");
                sb.AppendLine($"<text x=\"{F(x)}\" y=\"{height - bottom + 18}\" text-anchor=\"middle\">1e{d:0}</text>");
            }

            for (double d = minY; d <= maxY; d++)
            {
                double y = Y(Math.Pow(10, d));
                sb.AppendLine($"<line x1=\"{left}\" y1=\"{F(y)}\" x2=\"{width - right}\" y2=\"{F(y)}\" stroke=\"#ddd\"/>");
                sb.AppendLine($"<text x=\"{left - 8}\" y=\"{F(y + 4)}\" text-anchor=\"end\">1e{d:0}</text>");
            }

            sb.AppendLine($"<rect x=\"{left}\" y=\"{top}\" width=\"{width - left - right}\" height=\"{height - top - bottom}\" fill=\"none\" stroke=\"#333\"/>");
            sb.AppendLine($"<text x=\"{(left + width - right) / 2}\" y=\"{height - 15}\" text-anchor=\"middle\">time to fly all {shots.Length} shots (microseconds, log)</text>");
            sb.AppendLine($"<text transform=\"translate(18 {(top + height - bottom) / 2}) rotate(-90)\" text-anchor=\"middle\">worst landing error (m, log)</text>");
            for (int s = 0; s < series.Count; s++)
            {
                string colour = colours[s % colours.Length];
                var points = series[s].Where(r => !double.IsInfinity(r.WorstError)).Select(r => $"{F(X(r.TotalNanoseconds / 1000))},{F(Y(r.WorstError))}");
                sb.AppendLine($"<polyline fill=\"none\" stroke=\"{colour}\" stroke-width=\"2\" points=\"{string.Join(" ", points)}\"/>");
                foreach (Row r in series[s].Where(r => !double.IsInfinity(r.WorstError)))
                {
                    sb.AppendLine($"<circle cx=\"{F(X(r.TotalNanoseconds / 1000))}\" cy=\"{F(Y(r.WorstError))}\" r=\"3\" fill=\"{colour}\"><title>{series[s].Key} {r.Setting}: {E(r.WorstError)} m, {Us(r.TotalNanoseconds)} us</title></circle>");
                }

                double ly = top + 20 + 20 * s;
                sb.AppendLine($"<line x1=\"{width - right + 15}\" y1=\"{F(ly)}\" x2=\"{width - right + 40}\" y2=\"{F(ly)}\" stroke=\"{colour}\" stroke-width=\"2\"/>");
                sb.AppendLine($"<text x=\"{width - right + 46}\" y=\"{F(ly + 4)}\">{series[s].Key}</text>");
            }

            sb.AppendLine($"<text x=\"{width - right + 15}\" y=\"{top + 20 + 20 * series.Count + 10}\" font-size=\"10\">points: 1/30 ... 1/1000 s</text>");
            sb.AppendLine($"<text x=\"{width - right + 15}\" y=\"{top + 20 + 20 * series.Count + 24}\" font-size=\"10\">(adaptive: tol 1e-3 ... 1e-10)</text>");
            sb.AppendLine("</svg>");
            return sb.ToString();
        }

        private static string F(double v) => v.ToString("F1", Inv);
    }
}
