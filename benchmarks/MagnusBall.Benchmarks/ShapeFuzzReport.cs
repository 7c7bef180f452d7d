using System;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Threading.Tasks;
using MagnusBall.Fuzz;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Console mode "fuzz-shapes" (issue 40): the long version of ShapeFuzzTests. Seeded calls into FlightStepper, FixedStepDriver
    /// and TrajectoryPredictor built with random contact shapes (<see cref="StatefulFuzz.RunShapes"/>); prints the counts of each
    /// defect kind (changed after a throw, undocumented exceptions, unnamed, NaN, non-finite, tunnelling, calls over 10 s), the
    /// slowest call and the first failure of each kind with the calls that reproduce it. Usage: fuzz-shapes [calls] [seed] [minutes].
    /// With minutes, stops starting new objects after that long.
    /// </summary>
    internal static class ShapeFuzzReport
    {
        public static int Run(string[] args)
        {
            long calls = args.Length > 1 ? long.Parse(args[1], CultureInfo.InvariantCulture) : 200_000;
            int seed = args.Length > 2 ? int.Parse(args[2], CultureInfo.InvariantCulture) : 40;
            double minutes = args.Length > 3 ? double.Parse(args[3], CultureInfo.InvariantCulture) : double.PositiveInfinity;
            var fuzz = new StatefulFuzz(seed);
            var clock = Stopwatch.StartNew();
            // In chunks, so a time budget can end the run between objects (the calls of one chunk are the same for any budget).
            var run = Task.Run(() =>
            {
                for (long target = Math.Min(calls, 10_000); ; target = Math.Min(calls, target + 10_000))
                {
                    fuzz.RunShapes(target);
                    if (fuzz.Calls >= calls || clock.Elapsed.TotalMinutes > minutes)
                    {
                        return;
                    }
                }
            });
            long lastCalls = -1, named = -1;
            Func<string> lastCurrent = fuzz.Current;
            var sameSince = Stopwatch.StartNew();
            var lastPrint = Stopwatch.StartNew();
            while (!run.Wait(TimeSpan.FromSeconds(5)))
            {
                long now = fuzz.Calls;
                if (now != lastCalls || !ReferenceEquals(fuzz.Current, lastCurrent))
                {
                    lastCalls = now;
                    lastCurrent = fuzz.Current;
                    sameSince.Restart();
                }
                else if (sameSince.Elapsed > TimeSpan.FromSeconds(10) && now != named)
                {
                    // Once per call that has run over 10 s (a window of the 5 s polls can be missed when a poll is late).
                    named = now;
                    Console.WriteLine($"  still in call {now} after {sameSince.Elapsed.TotalSeconds:F0} s: {lastCurrent()}");
                }

                if (lastPrint.Elapsed.TotalSeconds >= 60)
                {
                    lastPrint.Restart();
                    Console.WriteLine($"  shapes: {now} calls, {fuzz.Defects} defects ({fuzz.Penetrations} tunnelled), {clock.Elapsed.TotalSeconds:F0} s");
                }
            }

            run.Wait();
            Console.WriteLine(
                $"Shapes (seed {seed}): {fuzz.Calls} calls in {clock.Elapsed.TotalSeconds:F0} s (FlightStepper {fuzz.ShapeStepperCalls}, FixedStepDriver {fuzz.ShapeDriverCalls}, " +
                $"TrajectoryPredictor {fuzz.ShapePredictorCalls}, constructors {fuzz.ConstructorCalls}, shape sets {fuzz.ShapeSets}): {fuzz.Throws} threw a documented exception; " +
                $"{fuzz.ShapeContacts} contacts ({fuzz.ShapeSettles} settled on a shape), {fuzz.PenetrationChecks} no-tunnelling checks");
            Console.WriteLine(
                $"defects: {fuzz.ChangedAfterThrow} changed after a throw, {fuzz.UndocumentedExceptions} undocumented exceptions, {fuzz.UnnamedArgumentErrors} without a parameter name, " +
                $"{fuzz.NaNs} NaN, {fuzz.NonFiniteStates} non-finite states, {fuzz.Penetrations} tunnelled (> {StatefulFuzz.PenetrationTolerance:R} m; by kind: " +
                string.Join(", ", StatefulFuzz.ShapeKindNames.Select((n, i) => $"{n} {fuzz.PenetrationsByKind[i]}")) + $"), {fuzz.Hangs} calls over 10 s; " +
                $"not defects: {fuzz.ShallowPenetrations} step ends 1e-6 m to 1 cm inside; {fuzz.UnstableSkips} fixed steps past their method's stability bound (their flights not judged from there)");
            Console.WriteLine($"deepest: {fuzz.DeepestPenetration:R} m");
            Console.WriteLine($"slowest call {fuzz.Slowest.TotalSeconds:F3} s: {fuzz.SlowestCall}");
            Console.WriteLine("time by type (stepper, driver, -, predictor): " + string.Join(", ", fuzz.TimeByType.Take(4).Select(t => $"{t.TotalSeconds:F0} s")));
            foreach (var pair in fuzz.FirstByKind)
            {
                Console.WriteLine($"---- first failure ({pair.Key}):\n{pair.Value}");
            }

            for (int i = 1; i < fuzz.PenetrationLogs.Count; i++)
            {
                Console.WriteLine($"---- tunnelling {i + 1}:\n{fuzz.PenetrationLogs[i]}");
            }

            return fuzz.Defects == 0 ? 0 : 1;
        }
    }
}
