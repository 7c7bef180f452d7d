using System;
using System.Diagnostics;
using MagnusBall.Integration;
using MathNet.Numerics.LinearAlgebra;

namespace MagnusBall.Benchmarks
{
    /// <summary>A rough Stopwatch timing of the peers (mode "quick-timing"): for a quick look only; the numbers in docs come from BenchmarkDotNet.</summary>
    internal static class QuickTiming
    {
        public static void Run()
        {
            var peers = new Peers();
            peers.Setup();
            var full = new StepCost { Method = "rk4", Model = "full" };
            full.Setup();
            var vac = new StepCost { Method = "rk4", Model = "vacuum" };
            vac.Setup();

            for (int round = 0; round < 3; round++)
            {
                Console.WriteLine($"MagnusBall RK4 (thesis model): {Time(() => peers.MagnusBallRk4(), 480):F1} ns/step");
                Console.WriteLine($"MagnusBall RK4 (full model):   {Time(() => full.Step(), 480):F1} ns/step");
                Console.WriteLine($"MagnusBall RK4 (vacuum):       {Time(() => vac.Step(), 480):F1} ns/step");
                long a0 = GC.GetAllocatedBytesForCurrentThread();
                peers.ThesisStyle();
                long thesisBytes = GC.GetAllocatedBytesForCurrentThread() - a0;
                Console.WriteLine($"thesis-style:                  {Time(() => peers.ThesisStyle(), 480):F1} ns/step, {thesisBytes / 480.0:F0} B/step (first call)");
                Console.WriteLine($"MathNet:                       {Time(() => peers.MathNet(), 480):F1} ns/step");
                FlightModel model = Scenarios.ThesisTennis();
                FlightState s = Scenarios.TennisDrive();
                Console.WriteLine($"Derivative (thesis model):     {Time(() => model.Derivative(s).Acceleration.X, 1):F1} ns");
                FlightModel fm = Scenarios.FullTennis();
                Console.WriteLine($"Derivative (full model):       {Time(() => fm.Derivative(s).Acceleration.X, 1):F1} ns");
                FlightModel dm = Scenarios.DragOnlyTennis();
                Console.WriteLine($"Derivative (drag-only model):  {Time(() => dm.Derivative(s).Acceleration.X, 1):F1} ns");
                double sp = 0.2;
                Console.WriteLine($"StepanekDrag.Evaluate:         {Time(() => Aerodynamics.StepanekDrag.Evaluate(sp += 1e-9), 1):F1} ns");
                Console.WriteLine($"StepanekLift.Evaluate:         {Time(() => Aerodynamics.StepanekLift.Evaluate(sp += 1e-9), 1):F1} ns");
            }
        }

        private static double Time(Func<double> body, int perCall)
        {
            double sink = 0;
            for (int i = 0; i < 2000; i++)
            {
                sink += body();
            }

            int calls = 4_000_000 / perCall;
            var process = Process.GetCurrentProcess();
            TimeSpan cpu0 = process.TotalProcessorTime;
            for (int i = 0; i < calls; i++)
            {
                sink += body();
            }

            process.Refresh();
            TimeSpan cpu = process.TotalProcessorTime - cpu0;
            if (sink == 42)
            {
                Console.WriteLine();
            }

            // CPU time of this process (not wall time): less disturbed by the other jobs on the shared machine.
            return cpu.TotalMilliseconds * 1e6 / ((double)calls * perCall);
        }
    }
}

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Mode "kernel NAME CALLS": runs one kernel (or one aim solve: aim-clear, aim-baseline, aim-corner, aim-speed) CALLS times after a warm-up, for counting CPU cycles with
    /// `perf stat -e cycles:u` (a run with CALLS = 0 gives the fixed start-up cost to subtract). Cycles spent in this
    /// process do not depend on what else the shared machine runs, unlike wall-clock time.
    /// </summary>
    internal static class Kernel
    {
        public static int Run(string name, long calls)
        {
            var peers = new Peers();
            peers.Setup();
            Func<double> body;
            int stepsPerCall = 480;
            switch (name)
            {
                case "rk4-thesis": body = peers.MagnusBallRk4; break;
                case "thesis-style": body = peers.ThesisStyle; break;
                case "mathnet": body = peers.MathNet; break;
                case "aim-clear":
                case "aim-baseline":
                case "aim-corner":
                case "aim-speed":
                {
                    var work = new Workloads();
                    work.Setup();
                    body = name == "aim-clear" ? work.AimClearNet : name == "aim-baseline" ? work.AimBaseline : name == "aim-corner" ? work.AimCorner : work.AimSpeed;
                    stepsPerCall = 1;
                    break;
                }

                default:
                    string[] parts = name.Split(':'); // e.g. step:rk4:full
                    var step = new StepCost { Method = parts[1], Model = parts[2] };
                    step.Setup();
                    body = step.Step;
                    break;
            }

            double sink = 0;
            for (int i = 0; i < 3000; i++)
            {
                sink += body();
            }

            System.Threading.Thread.Sleep(200); // let tiered compilation finish in the background
            for (int i = 0; i < 1000; i++)
            {
                sink += body();
            }

            TimeSpan cpu = System.Diagnostics.Process.GetCurrentProcess().TotalProcessorTime;
            for (long i = 0; i < calls; i++)
            {
                sink += body();
            }

            double perCall = calls > 0 ? (System.Diagnostics.Process.GetCurrentProcess().TotalProcessorTime - cpu).TotalMilliseconds * 1e3 / calls : 0;
            Console.WriteLine($"{name}: {calls} calls x {stepsPerCall} steps, {perCall:F2} us CPU per call ({sink:E1})");
            return 0;
        }
    }
}
