using BenchmarkDotNet.Attributes;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// Issue 11's targets as BenchmarkDotNet ratios against one thesis-style 2 s shot (480 RK4 steps, the baseline, one
    /// call = one shot): MagnusBall's RK4 over the same 480 steps, 2 s predicted shots with events, the aim solves, 1,000 and
    /// 10,000 balls in a <c>BallBatch</c> through one 60 FPS frame, and 1,000 FixedStepDrivers one at a time through one frame
    /// (default stable RK4 and plain RK4 on the full model, plain RK4 on the thesis model), and the same balls through
    /// <c>RungeKutta4.Advance</c> one at a time, the kernel alone (the floor of any per-ball loop on the full model). Also the full tennis model in the
    /// thesis's style (<see cref="ThesisStyleTennisBall"/>), the naive code of the full-model rows' model.
    /// </summary>
    [Config(typeof(ShortConfig))]
    public class PeerShots
    {
        private readonly Workloads _work = new Workloads();

        [GlobalSetup]
        public void Setup() => _work.Setup();

        [Benchmark(Baseline = true, Description = "thesis-style 480-step shot")]
        public double ThesisShot() => _work.ThesisShot();

        [Benchmark(Description = "thesis-style 480-step shot, full tennis model")]
        public double ThesisStyleTennisShot() => _work.ThesisStyleTennisShot();

        [Benchmark(Description = "MagnusBall RK4 480 steps, thesis ODE")]
        public double Rk4Thesis() => _work.Rk4ThesisShot();

        [Benchmark(Description = "MagnusBall RK4 480 steps, full tennis model")]
        public double Rk4Full() => _work.Rk4FullShot();

        [Benchmark(Description = "predict 2 s with events, thesis model")]
        public double PredictThesis() => _work.PredictThesis();

        [Benchmark(Description = "predict 2 s with events, full tennis model")]
        public double PredictFull() => _work.PredictFull();

        [Benchmark(Description = "BallBatch 1,000 balls, one 60 FPS frame")]
        public double Batch1000() => _work.Batch1000();

        [Benchmark(Description = "BallBatch 10,000 balls, one 60 FPS frame")]
        public double Batch10000() => _work.Batch10000();

        [Benchmark(Description = "1,000 FixedStepDrivers one at a time, one frame")]
        public double Drivers1000() => _work.Drivers1000();

        [Benchmark(Description = "1,000 FixedStepDrivers (rk4), one frame")]
        public double Drivers1000Rk4() => _work.Drivers1000Rk4();

        [Benchmark(Description = "1,000 FixedStepDrivers (rk4), thesis model, one frame")]
        public double Drivers1000Thesis() => _work.Drivers1000Thesis();

        [Benchmark(Description = "1,000 balls by RungeKutta4.Advance(4), full tennis model (the drivers' floor)")]
        public double KernelFloor1000() => _work.KernelFloor1000();

        [Benchmark(Description = "10,000 balls by RungeKutta4.Advance(4), full tennis model (the scalar kernel)")]
        public double KernelFloor10000() => _work.KernelFloor10000();

        [Benchmark(Description = "AimSolver.MinimumElevationToClear (net)")]
        public double AimClearNet() => _work.AimClearNet();

        [Benchmark(Description = "AimSolver.ElevationToReach (baseline)")]
        public double AimBaseline() => _work.AimBaseline();

        [Benchmark(Description = "AimSolver.SpeedToReach")]
        public double AimSpeed() => _work.AimSpeed();

        [Benchmark(Description = "AimSolver.AnglesToReach (corner)")]
        public double AimCorner() => _work.AimCorner();
    }
}
