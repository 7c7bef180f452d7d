using System;
using System.Diagnostics;
using MagnusBall.Flight;
using MagnusBall.Integration;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Mode "adaptive-steps [rounds]": what one Dormand-Prince step costs on the full tennis model, piece by piece, in one
    /// process (interleaved rounds, CPU time, the best round kept, as "ratios"): the kernel's six stages, the same stages
    /// through FlightModel.Derivative, one FlightModel.Derivative, DormandPrince54.TryStep (stages, error norm, controller,
    /// dense output), the RK4 kernel step, and a whole adaptive step of the flight core with an event set (docs/performance.md,
    /// "Aim solves"). Each from the benchmark's drive with a 0.01 s step.
    /// </summary>
    internal static class AdaptiveTiming
    {
        private const int Repeats = 100;

        public static int Run(int rounds)
        {
            FlightModel model = Scenarios.FullTennis();
            FlightState launch = Scenarios.TennisDrive();
            StateDerivative k1 = model.Derivative(launch);
            var method = new DormandPrince54(1e-8, 1e-8);
            var step = new DormandPrince54Step();
            var flight = new FlightStepper(model, RungeKutta4.Instance, FlightEventSet.ForModel(model));
            var items = new (string Name, Func<double> Body)[]
            {
                ("DP54 stages, kernel", () =>
                {
                    double x = 0;
                    DormandPrince54Stages stages = default; // reused, as the stepper reuses its step's stages
                    for (int i = 0; i < Repeats; i++)
                    {
                        FlightKernel.Of(model).DormandPrince54(launch, k1, 0.01, ref stages);
                        x += stages.End.Position.X;
                    }

                    return x;
                }),
                ("DP54 stages, FlightModel.Derivative", () =>
                {
                    double x = 0;
                    DormandPrince54Stages stages = default; // reused, as the stepper reuses its step's stages
                    for (int i = 0; i < Repeats; i++)
                    {
                        DormandPrince54.GeneralStages(model, launch, k1, 0.01, ref stages);
                        x += stages.End.Position.X;
                    }

                    return x;
                }),
                ("one FlightModel.Derivative", () =>
                {
                    double x = 0;
                    for (int i = 0; i < Repeats; i++)
                    {
                        x += model.Derivative(launch).Acceleration.X;
                    }

                    return x;
                }),
                ("DormandPrince54.TryStep", () =>
                {
                    double x = 0;
                    for (int i = 0; i < Repeats; i++)
                    {
                        method.TryStepInPlace(model, launch, k1, 0.01, ref step);
                        x += step.NextStep;
                    }

                    return x;
                }),
                ("RK4 kernel step", () =>
                {
                    double x = 0;
                    for (int i = 0; i < Repeats; i++)
                    {
                        x += FlightKernel.Of(model).RungeKutta4(launch, k1, 0.01, out _).Position.X;
                    }

                    return x;
                }),
                ("core adaptive step, events", () =>
                {
                    flight.Reset(launch);
                    for (int i = 0; i < Repeats; i++)
                    {
                        flight.TryStepAdaptive(method, 0.01);
                    }

                    return flight.State.Position.X;
                }),
            };

            var best = new double[items.Length];
            for (int i = 0; i < best.Length; i++)
            {
                best[i] = double.MaxValue;
            }

            double sink = 0;
            for (int r = 0; r < rounds; r++)
            {
                for (int i = 0; i < items.Length; i++)
                {
                    for (int w = 0; w < 20; w++)
                    {
                        sink += items[i].Body();
                    }

                    int calls = 0;
                    TimeSpan start = Process.GetCurrentProcess().TotalProcessorTime;
                    var clock = Stopwatch.StartNew();
                    while (clock.Elapsed.TotalSeconds < 0.1)
                    {
                        sink += items[i].Body();
                        calls++;
                    }

                    double ns = (Process.GetCurrentProcess().TotalProcessorTime - start).TotalMilliseconds * 1e6 / (calls * (double)Repeats);
                    best[i] = Math.Min(best[i], ns);
                }
            }

            Console.WriteLine($"per step (ns), full tennis model, 0.01 s, best of {rounds} rounds ({sink:E1})");
            for (int i = 0; i < items.Length; i++)
            {
                Console.WriteLine($"{items[i].Name,-38} {best[i],8:F0}");
            }

            return 0;
        }
    }
}
