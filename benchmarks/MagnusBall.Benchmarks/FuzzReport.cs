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
    /// exceptions. Usage: fuzz [files] [calls] [seed] [maxStepsKept].
    /// </summary>
    internal static class FuzzReport
    {
        public static int Run(string[] args)
        {
            int files = args.Length > 1 ? int.Parse(args[1], CultureInfo.InvariantCulture) : 10_000;
            long calls = args.Length > 2 ? long.Parse(args[2], CultureInfo.InvariantCulture) : 1_000_000;
            int seed = args.Length > 3 ? int.Parse(args[3], CultureInfo.InvariantCulture) : 2026;
            double kept = args.Length > 4 ? double.Parse(args[4], CultureInfo.InvariantCulture) : 1e6;

            var generator = new HostileJson(seed) { MaxStepsKept = kept };
            int[] counts = new int[Enum.GetValues<CliOutcome>().Length];
            int hangs = 0;
            TimeSpan slowest = TimeSpan.Zero, total = TimeSpan.Zero;
            string? firstBad = null;
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

                slowest = time > slowest ? time : slowest;
                if (outcome is not (CliOutcome.Success or CliOutcome.InputError))
                {
                    firstBad ??= $"file {i}: {outcome}: {detail}\n{json}";
                }
            }

            Console.WriteLine($"CLI: {files} hostile files (seed {seed}, accepted flights kept to {kept:0e0} steps): " +
                              string.Join(", ", Enum.GetValues<CliOutcome>().Select(o => $"{o} {counts[(int)o]}")) +
                              $"; hangs (> 10 s) {hangs}; slowest {slowest.TotalSeconds:F2} s, total {total.TotalSeconds:F0} s");

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

            bool clean = counts[(int)CliOutcome.Crash] + counts[(int)CliOutcome.InvalidOutput] + counts[(int)CliOutcome.BadError] + hangs == 0 &&
                         physics.NaNs + physics.InfiniteForModerate + physics.UnnamedArgumentErrors + physics.UndocumentedExceptions == 0;
            return clean ? 0 : 1;
        }
    }
}
