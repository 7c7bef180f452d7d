using System;
using System.Diagnostics;
using System.Globalization;
using System.Numerics;
using System.Runtime.InteropServices;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Mode "ratios": issue 11's headline ratios in one short run (about 10-20 s), every workload timed in the same process,
    /// interleaved round by round, in CPU time of the process, the best round of each kept (on a shared machine the
    /// fastest round is the least disturbed one). A quick check, not BenchmarkDotNet: the tables in docs/performance.md say which is which. Also
    /// built for Mono (benchmarks/MagnusBall.Ratios.Mono, docs/performance.md).
    /// </summary>
    public static class Ratios
    {
        private delegate double Work();

        /// <summary>Runs the comparison and prints it; returns 0.</summary>
        /// <param name="rounds">Rounds (each times every workload for about <paramref name="secondsPerWorkload"/> s).</param>
        /// <param name="secondsPerWorkload">Time per workload and round, s.</param>
        public static int Run(int rounds = 5, double secondsPerWorkload = 0.25)
        {
            var work = new Workloads();
            work.Setup();
            bool mono = Type.GetType("Mono.Runtime") != null;
            string runtime = mono ? "Mono " + MonoVersion() : RuntimeInformation.FrameworkDescription;

            var items = new (string Name, Work Body)[]
            {
                ("thesis-style 480-step shot", work.ThesisShot),
                ("RK4 480 steps, thesis ODE", work.Rk4ThesisShot),
                ("RK4 480 steps, full tennis", work.Rk4FullShot),
                ("predict 2 s + events, thesis", work.PredictThesis),
                ("predict 2 s + events, full", work.PredictFull),
                ("aim MinimumElevationToClear", work.AimClearNet),
                ("aim ElevationToReach", work.AimBaseline),
                ("aim AnglesToReach", work.AimCorner),
                ("aim SpeedToReach", work.AimSpeed),
                ("BallBatch 1,000, one frame", work.Batch1000),
                ("BallBatch 10,000, one frame", work.Batch10000),
                ("1,000 drivers (stable-rk4), frame", work.Drivers1000),
                ("1,000 drivers (rk4), frame", work.Drivers1000Rk4),
                ("RK4 480 steps, thesis, one Advance", work.Rk4ThesisRun),
                ("aim ElevationToReach, RK4 trials", work.AimBaselineFixed),
                ("aim AnglesToReach, RK4 trials", work.AimCornerFixed),
                ("1,000 drivers (rk4), thesis model", work.Drivers1000Thesis),
                ("RK4 480 steps, thesis, 480 Advance(1)", work.Rk4ThesisAdvanceEach),
                ("thesis-style shot, full tennis", work.ThesisStyleTennisShot),
                ("RK4 Advance(4) x 1,000 balls, full", work.KernelFloor1000),
                ("RK4 Advance(4) x 10,000 balls, full", work.KernelFloor10000),
                ("aim AnglesToReach, the lob", work.AimCornerLob),
                ("aim AnglesToReach over a 3 m wall", work.AimCornerOverWall),
                ("aim AnglesToReach, out of reach", work.AimUnreachable),
                ("SwingAim club, 170 m flag", work.SwingClub),
                ("SwingAim club, out of reach", work.SwingClubUnreachable),
            };

            var best = new double[items.Length];
            var bytes = new long[items.Length];
            var missing = new string?[items.Length];
            for (int i = 0; i < items.Length; i++)
            {
                best[i] = double.MaxValue;
                try
                {
                    items[i].Body(); // warm-up (JIT, statics)
                    items[i].Body();
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    items[i].Body();
                    bytes[i] = GC.GetAllocatedBytesForCurrentThread() - before;
                }
                catch (MissingMethodException e)
                {
                    // Mono 6.8's netstandard 2.1 facade lacks some Span members the library's event code calls.
                    missing[i] = e.Message;
                    best[i] = double.NaN;
                }
            }

            for (int round = 0; round < rounds; round++)
            {
                for (int i = 0; i < items.Length; i++)
                {
                    if (missing[i] == null)
                    {
                        best[i] = Math.Min(best[i], Time(items[i].Body, secondsPerWorkload));
                    }
                }
            }

            double shot = best[0];
            Console.WriteLine($"MagnusBall ratios: {runtime}, {RuntimeInformation.ProcessArchitecture}, {Environment.ProcessorCount} cores; " +
                $"Vector<double>: {Vector<double>.Count} lanes, accelerated {Vector.IsHardwareAccelerated}; best of {rounds} rounds of {secondsPerWorkload:0.##} s.");
            Console.WriteLine("unit U = one thesis-style 480-step shot. The machine may be shared: compare ratios, not times.");
            Console.WriteLine();
            Console.WriteLine($"{"workload",-36} {"time",12} {"x U",9} {"bytes/call",11}");
            for (int i = 0; i < items.Length; i++)
            {
                Console.WriteLine(missing[i] != null
                    ? $"{items[i].Name,-36} does not run here: {missing[i]}"
                    : $"{items[i].Name,-36} {Format(best[i]),12} {best[i] / shot,9:0.000} {bytes[i],11}");
            }

            double rk4Limit = mono ? 0.8 : 0.6;
            Console.WriteLine();
            Console.WriteLine("targets (issue 11):");
            Report($"RK4 on the thesis ODE <= {rk4Limit:0.0} x thesis-style (480 IIntegrator.Step calls)", best[1] / shot, rk4Limit);
            Report($"  (the same in one RungeKutta4.Advance call)", best[13] / shot, rk4Limit);
            Report($"  (the same as 480 RungeKutta4.Advance calls of one step)", best[17] / shot, rk4Limit);
            Report("predicted 2 s shot + events, thesis model <= 1 U", best[3] / shot, 1.0);
            Report("predicted 2 s shot + events, full model <= 1.6 U", best[4] / shot, 1.6);
            double worstAim = Math.Max(Math.Max(best[5], best[6]), Math.Max(best[7], best[8]));
            Report("every aim solve <= 1 U (worst)", worstAim / shot, 1.0);
            Report("every aim solve < 0.1 ms (worst, ms)", worstAim * 1e3, 0.1);
            Report("10,000 balls per 60 FPS frame < 3 ms (ms)", best[10] * 1e3, 3.0);
            Info("  (the scalar kernel alone, not a target: the same frame as 10,000 RungeKutta4.Advance calls of 4 steps, ms)", best[20] * 1e3);
            Report("1,000 drivers one at a time <= 8 U (default stable-rk4)", best[11] / shot, 8.0);
            Report("1,000 drivers one at a time <= 8 U (rk4)", best[12] / shot, 8.0);
            Info("  (the floor, not a target: the same balls by 1,000 RungeKutta4.Advance calls of 4 steps; no stepper, events or driver)", best[19] / shot);
            Report("  (rk4 on the thesis model: per-step parity with the thesis-style shot)", best[16] / shot, 8.0);
            long library = 0;
            for (int i = 1; i < items.Length; i++)
            {
                if (i != 18) // the full model's thesis-style shot, not the library
                {
                    library = Math.Max(library, bytes[i]);
                }
            }

            Report("0 bytes per step, shot, aim solve, batch frame (most bytes in one call)", library, 0);

            // Not issue 11's targets (those are against U): the full model's workloads against the naive code of the same
            // model, which a game on that model replaces.
            double fullShot = best[18];
            Console.WriteLine();
            Console.WriteLine("the full tennis model against the same model in the thesis's style (U_full = its 480-step shot):");
            Report("RK4 480 steps, full tennis <= 1 U_full", best[2] / fullShot, 1.0);
            Report("predicted 2 s shot + events, full model <= 1 U_full", best[4] / fullShot, 1.0);
            Report("1,000 drivers one at a time <= 8 U_full (default stable-rk4; per-step parity)", best[11] / fullShot, 8.0);
            Report("1,000 drivers one at a time <= 8 U_full (rk4; per-step parity)", best[12] / fullShot, 8.0);
            return 0;
        }

        /// <summary>
        /// Mode "workload NAME SECONDS": calls one workload of <see cref="Workloads"/> (by method name) for about SECONDS s
        /// of CPU time after a warm-up, and prints the time per call: for a profiler (perf record with
        /// DOTNET_PerfMapEnabled=1) or the JIT's listing (DOTNET_JitDisasm) of one workload alone.
        /// </summary>
        public static int Profile(string name, double seconds)
        {
            var work = new Workloads();
            work.Setup();
            string[] names = name.Split(',');
            var bodies = new Work[names.Length];
            for (int i = 0; i < names.Length; i++)
            {
                System.Reflection.MethodInfo? method = typeof(Workloads).GetMethod(names[i]);
                if (method == null)
                {
                    Console.Error.WriteLine($"no workload '{names[i]}'");
                    return 2;
                }

                bodies[i] = (Work)Delegate.CreateDelegate(typeof(Work), work, method);
                Time(bodies[i], 0.3); // warm-up: tiered compilation reaches its optimised code
            }

            System.Threading.Thread.Sleep(200);
            // Wall-clock time of short batches (about 2 ms), the fastest batch of each kept: on a shared machine a batch
            // short against the scheduler's time slice often runs undisturbed, so the minimum is the code's own time.
            var best = new double[names.Length];
            var batch = new int[names.Length];
            for (int i = 0; i < best.Length; i++)
            {
                best[i] = double.MaxValue;
                var watch = Stopwatch.StartNew();
                int calls = 0;
                while (watch.Elapsed.TotalSeconds < 0.01)
                {
                    bodies[i]();
                    calls++;
                }

                batch[i] = Math.Max(1, (int)(calls * 0.002 / watch.Elapsed.TotalSeconds));
            }

            var total = Stopwatch.StartNew();
            double sink = 0;
            while (total.Elapsed.TotalSeconds < seconds)
            {
                for (int i = 0; i < names.Length; i++)
                {
                    long start = Stopwatch.GetTimestamp();
                    for (int k = 0; k < batch[i]; k++)
                    {
                        sink += bodies[i]();
                    }

                    double perCall = (Stopwatch.GetTimestamp() - start) / (double)Stopwatch.Frequency / batch[i];
                    best[i] = Math.Min(best[i], perCall);
                }
            }

            if (double.IsNaN(sink))
            {
                Console.WriteLine("(NaN result)");
            }

            for (int i = 0; i < names.Length; i++)
            {
                Console.WriteLine($"{names[i],-24} {Format(best[i]),12} {best[i] / best[0],8:0.000} x the first");
            }

            return 0;
        }

        private static void Info(string what, double value) =>
            Console.WriteLine($"         {what}: {value.ToString("0.000", CultureInfo.InvariantCulture)}");

        private static void Report(string target, double value, double limit) =>
            Console.WriteLine(double.IsNaN(value) ? $"  n/a    {target}: a workload does not run on this runtime" :
$"  {(value <= limit ? "met   " : "MISSED")} {target}: {value.ToString("0.000", CultureInfo.InvariantCulture)}" +
                (value <= limit ? string.Empty : $" ({value / Math.Max(limit, 1e-300):0.0}x the limit)"));

        // CPU seconds per call (this process's processor time, not the wall clock: on a shared machine the wall clock
        // counts the other processes' turns too), calling until the time is spent.
        private static double Time(Work body, double seconds)
        {
            double sink = 0;
            long calls = 0;
            Process process = Process.GetCurrentProcess();
            TimeSpan start = process.TotalProcessorTime;
            double spent;
            do
            {
                for (int i = 0; i < 8; i++)
                {
                    sink += body();
                }

                calls += 8;
                process.Refresh();
                spent = (process.TotalProcessorTime - start).TotalSeconds;
            }
            while (spent < seconds);
            double perCall = spent / calls;
            if (double.IsNaN(sink))
            {
                Console.WriteLine("(NaN result)");
            }

            return perCall;
        }

        private static string Format(double seconds) =>
            seconds >= 1e-3 ? $"{seconds * 1e3:0.000} ms" : $"{seconds * 1e6:0.0} us";

        private static string MonoVersion()
        {
            Type? type = Type.GetType("Mono.Runtime");
            object? name = type?.GetMethod("GetDisplayName", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Static)?.Invoke(null, null);
            return name?.ToString() ?? "?";
        }
    }
}
