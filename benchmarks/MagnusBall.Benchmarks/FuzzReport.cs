using System;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Threading.Tasks;
using MagnusBall.Fuzz;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Console mode "fuzz" (issue 15): the long version of the suite's fuzz tests. 10,000 seeded hostile CLI files
    /// through the in-process entry point (plain, --svg, --samples, --csv in turn) and 1,000,000 seeded hostile
    /// physics-API calls; prints the counts of crashes, hangs (a run over 10 s), invalid outputs and undocumented
    /// exceptions; then 1,000,000 seeded hostile calls into the stateful types (<see cref="StatefulFuzz"/>: every
    /// throwing call must leave its object bitwise unchanged). Usage: fuzz [files] [calls] [seed] [maxStepsKept] [statefulCalls].
    /// </summary>
    internal static class FuzzReport
    {
        public static int Run(string[] args)
        {
            int files = args.Length > 1 ? int.Parse(args[1], CultureInfo.InvariantCulture) : 10_000;
            long calls = args.Length > 2 ? long.Parse(args[2], CultureInfo.InvariantCulture) : 1_000_000;
            int seed = args.Length > 3 ? int.Parse(args[3], CultureInfo.InvariantCulture) : 2026;
            double kept = args.Length > 4 ? double.Parse(args[4], CultureInfo.InvariantCulture) : 1e6;
            long statefulCalls = args.Length > 5 ? long.Parse(args[5], CultureInfo.InvariantCulture) : 1_000_000;

            var generator = new HostileJson(seed) { MaxStepsKept = kept };
            int[] counts = new int[Enum.GetValues<CliOutcome>().Length];
            int hangs = 0;
            TimeSpan slowest = TimeSpan.Zero, total = TimeSpan.Zero;
            string? firstBad = null, slowestFile = null;
            for (int i = 0; i < files; i++)
            {
                string json = generator.Next();
                int variant = i;
                // On a worker, so a run that never returned would still be counted (as a hang) and reported.
                var run = Task.Run(() => CliFuzz.Run(json, variant));
                if (!run.Wait(TimeSpan.FromSeconds(120)))
                {
                    hangs++;
                    counts[(int)CliOutcome.Crash]++;
                    firstBad ??= $"file {i} did not return in 120 s:\n{json}";
                    continue;
                }

                (CliOutcome outcome, string detail, TimeSpan time) = run.Result;
                counts[(int)outcome]++;
                total += time;
                if (time.TotalSeconds > 10)
                {
                    hangs++;
                    firstBad ??= $"file {i} ran {time.TotalSeconds:F1} s:\n{json}";
                }

                if (time > slowest)
                {
                    slowest = time;
                    slowestFile = $"file {i} (variant {i % 4}), {outcome}: {detail.Trim()}\n{json}";
                }

                if (outcome is not (CliOutcome.Success or CliOutcome.InputError))
                {
                    firstBad ??= $"file {i}: {outcome}: {detail}\n{json}";
                }
            }

            Console.WriteLine($"CLI: {files} hostile files (seed {seed}, accepted flights kept to {kept:0e0} steps): " +
                              string.Join(", ", Enum.GetValues<CliOutcome>().Select(o => $"{o} {counts[(int)o]}")) +
                              $"; hangs (> 10 s) {hangs}; slowest {slowest.TotalSeconds:F2} s, total {total.TotalSeconds:F0} s");
            if (slowestFile != null)
            {
                Console.WriteLine("slowest CLI file: " + slowestFile);
            }

            var physics = new PhysicsFuzz(seed);
            var clock = Stopwatch.StartNew();
            physics.Run(calls);
            Console.WriteLine($"Physics API: {physics.Calls} hostile calls in {clock.Elapsed.TotalSeconds:F0} s: {physics.ArgumentErrors} refused with an ArgumentException " +
                              $"({physics.UnnamedArgumentErrors} without a parameter name), {physics.NaNs} NaN results, " +
                              $"{physics.InfiniteForModerate} infinite results for moderate input, {physics.UndocumentedExceptions} undocumented exceptions");
            if (firstBad != null || physics.FirstFailure != null)
            {
                Console.WriteLine("first failure: " + (firstBad ?? physics.FirstFailure));
            }

            StatefulFuzz stateful = RunStateful(seed, statefulCalls);
            bool clean = counts[(int)CliOutcome.Crash] + counts[(int)CliOutcome.InvalidOutput] + counts[(int)CliOutcome.BadError] + hangs == 0 &&
                         physics.NaNs + physics.InfiniteForModerate + physics.UnnamedArgumentErrors + physics.UndocumentedExceptions == 0 &&
                         stateful.Defects == 0;
            return clean ? 0 : 1;
        }

        // The stateful types, on a worker: the main thread prints progress and names any call running over 10 s.
        private static StatefulFuzz RunStateful(int seed, long calls)
        {
            var fuzz = new StatefulFuzz(seed);
            var clock = Stopwatch.StartNew();
            var run = Task.Run(() => fuzz.Run(calls));
            long lastCalls = -1;
            Func<string> lastCurrent = fuzz.Current;
            var sameSince = Stopwatch.StartNew();
            while (!run.Wait(TimeSpan.FromSeconds(5)))
            {
                long now = fuzz.Calls;
                if (now != lastCalls || !ReferenceEquals(fuzz.Current, lastCurrent))
                {
                    lastCalls = now;
                    lastCurrent = fuzz.Current;
                    sameSince.Restart();
                }
                else if (sameSince.Elapsed > TimeSpan.FromSeconds(10) && sameSince.Elapsed <= TimeSpan.FromSeconds(15))
                {
                    Console.WriteLine($"  still in call {now} after {sameSince.Elapsed.TotalSeconds:F0} s: {lastCurrent()}");
                }

                if (clock.Elapsed.TotalSeconds % 60 < 5)
                {
                    Console.WriteLine($"  stateful: {now} calls, {fuzz.Defects} defects, {clock.Elapsed.TotalSeconds:F0} s");
                }
            }

            run.Wait();
            Console.WriteLine(
                $"Stateful API: {fuzz.Calls} hostile calls in {clock.Elapsed.TotalSeconds:F0} s (FlightStepper {fuzz.StepperCalls}, FixedStepDriver {fuzz.DriverCalls}, " +
                $"BallBatch {fuzz.BatchCalls}, TrajectoryPredictor {fuzz.PredictorCalls}, AimSolver {fuzz.AimCalls}, constructors {fuzz.ConstructorCalls}): " +
                $"{fuzz.Throws} threw a documented exception; {fuzz.ChangedAfterThrow} changed after a throw, {fuzz.UndocumentedExceptions} undocumented exceptions, " +
                $"{fuzz.UnnamedArgumentErrors} without a parameter name, {fuzz.NaNs} NaN, {fuzz.NonFiniteStates} non-finite states, {fuzz.Hangs} calls over 10 s; " +
                $"slowest call {fuzz.Slowest.TotalSeconds:F2} s: {fuzz.SlowestCall}");
            Console.WriteLine("  time by type (stepper, driver, batch, predictor, aim): " + string.Join(", ", fuzz.TimeByType.Select(t => $"{t.TotalSeconds:F0} s")));
            foreach (var pair in fuzz.FirstByKind)
            {
                Console.WriteLine($"first stateful failure ({pair.Key}): {pair.Value}");
            }

            return fuzz;
        }
    }
}
