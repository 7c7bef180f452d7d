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
            for (int round = 0; round < 3; round++)
            {
                Console.WriteLine($"MagnusBall RK4 (thesis model): {Time(() => peers.MagnusBallRk4(), 480):F1} ns/step");
                Console.WriteLine($"MagnusBall RK4 (full model):   {Time(() => full.Step(), 480):F1} ns/step");
                Console.WriteLine($"thesis-style:                  {Time(() => peers.ThesisStyle(), 480):F1} ns/step");
                Console.WriteLine($"MathNet:                       {Time(() => peers.MathNet(), 480):F1} ns/step");
                FlightModel model = Scenarios.ThesisTennis();
                FlightState s = Scenarios.TennisDrive();
                Console.WriteLine($"Derivative (thesis model):     {Time(() => model.Derivative(s).Acceleration.X, 1):F1} ns");
                FlightModel fm = Scenarios.FullTennis();
                Console.WriteLine($"Derivative (full model):       {Time(() => fm.Derivative(s).Acceleration.X, 1):F1} ns");
            }
        }

        private static double Time(Func<double> body, int perCall)
        {
            double sink = 0;
            for (int i = 0; i < 2000; i++)
            {
                sink += body();
            }

            int calls = 20_000_00 / perCall;
            var watch = Stopwatch.StartNew();
            for (int i = 0; i < calls; i++)
            {
                sink += body();
            }

            watch.Stop();
            if (sink == 42)
            {
                Console.WriteLine();
            }

            return watch.Elapsed.TotalMilliseconds * 1e6 / ((double)calls * perCall);
        }
    }
}
