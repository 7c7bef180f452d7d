using System;
using System.IO;
using BenchmarkDotNet.Running;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Entry point. With no mode or a BenchmarkDotNet argument (--filter ...), runs the benchmarks; otherwise one of the
    /// report modes: "ratios" (issue 11's targets in one short run; optional rounds and seconds per workload), "extremes" (full matrix),
    /// "extremes-quick", "blowup", "work-precision", "peers-check", "fuzz" (issue 15's long hostile-input run), "fuzz-shapes" (issue 40's contact shapes under the stateful fuzz), "adaptive-steps"
    /// (the cost of one Dormand-Prince step, piece by piece).
    /// </summary>
    public static class Program
    {
        public static int Main(string[] args)
        {
            string mode = args.Length > 0 ? args[0] : string.Empty;
            switch (mode)
            {
                case "extremes":
                    Console.WriteLine(ExtremesReport.Matrix(quick: false));
                    return 0;
                case "extremes-quick":
                    Console.WriteLine(ExtremesReport.Matrix(quick: true));
                    return 0;
                case "ratios":
                case "--ratios":
                    return Ratios.Run(
                        args.Length > 1 ? int.Parse(args[1], System.Globalization.CultureInfo.InvariantCulture) : 5,
                        args.Length > 2 ? double.Parse(args[2], System.Globalization.CultureInfo.InvariantCulture) : 0.25);
                case "adaptive-steps":
                    return AdaptiveTiming.Run(args.Length > 1 ? int.Parse(args[1], System.Globalization.CultureInfo.InvariantCulture) : 10);
                case "quick-timing":
                    QuickTiming.Run();
                    return 0;
                case "work-precision":
                    WorkPrecisionReport.Run(args.Length > 1 ? args[1] : "docs");
                    return 0;
                case "kernel":
                    return Kernel.Run(args[1], long.Parse(args[2], System.Globalization.CultureInfo.InvariantCulture));
                case "workload":
                    return Ratios.Profile(args[1], double.Parse(args[2], System.Globalization.CultureInfo.InvariantCulture));
                case "peers-check":
                    {
                        var peers = new Peers();
                        peers.Setup();
                        Console.WriteLine($"x after 480 steps: MagnusBall {peers.MagnusBallRk4():R}, MathNet {peers.MathNet():R}, thesis-style {peers.ThesisStyle():R}");
                        // The full-model peer must fly the library's model: RK4 on the same ODE with the laws evaluated
                        // differently (Math.Pow against the table, the lift unfolded) differs by rounding only, far below 1e-9.
                        double worst = 0;
                        foreach ((string name, FlightState start) in new[]
                        {
                            ("the 40 m/s topspin drive", Scenarios.TennisDrive()),
                            ("a 50 m/s serve with sidespin", Scenarios.Launch(2.5, 50, -3, 0, Spin.FromRpm(1500))),
                            ("a 25 m/s slice, backspin and sidespin", Scenarios.Launch(1, 25, 15, -Spin.FromRpm(1500), -Spin.FromRpm(800))),
                        })
                        {
                            double difference = ThesisStyleTennisBall.DifferenceFromLibrary(start, out FlightState end);
                            worst = Math.Max(worst, difference);
                            Console.WriteLine($"full tennis model, {name}: after 480 steps x = {end.Position.X:R} m; " +
                                $"largest relative difference of position, velocity and spin from the thesis-style code {difference:E1}");
                        }

                        return worst <= 1e-9 ? 0 : 1;
                    }

                case "fuzz":
                    return FuzzReport.Run(args);
                case "fuzz-shapes":
                    return ShapeFuzzReport.Run(args);
                case "blowup":
                    Console.WriteLine(ExtremesReport.BlowUp());
                    return 0;
                default:
                    BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
                    return 0;
            }
        }
    }
}
