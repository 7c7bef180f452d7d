using System;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Diagnosers;
using BenchmarkDotNet.Jobs;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MathNet.Numerics.LinearAlgebra;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// A short job (the machine is shared): 1 launch, 3 warm-up and 7 measured iterations, with the memory diagnoser.
    /// Set MAGNUSBALL_DISASM=1 to add the disassembly diagnoser.
    /// </summary>
    public sealed class ShortConfig : ManualConfig
    {
        public ShortConfig()
        {
            AddJob(Job.Default.WithLaunchCount(1).WithWarmupCount(3).WithIterationCount(7).WithId("Short"));
            AddDiagnoser(MemoryDiagnoser.Default);
            if (Environment.GetEnvironmentVariable("MAGNUSBALL_DISASM") == "1")
            {
                AddDiagnoser(new DisassemblyDiagnoser(new DisassemblyDiagnoserConfig(maxDepth: 3, exportGithubMarkdown: true)));
            }
        }
    }

    /// <summary>Cost of one step of each integrator on the full tennis model, drag only and vacuum (480 steps per call).</summary>
    [Config(typeof(ShortConfig))]
    public class StepCost
    {
        public const int Steps = 480;
        private FlightModel _model = null!;
        private IIntegrator _integrator = null!;
        private FlightState _start;

        [Params("euler", "semi-implicit-euler", "heun", "rk4", "dp54", "stable-rk4")]
        public string Method { get; set; } = "rk4";

        [Params("full", "drag-only", "vacuum")]
        public string Model { get; set; } = "full";

        [GlobalSetup]
        public void Setup()
        {
            _model = Model == "full" ? Scenarios.FullTennis() : Model == "drag-only" ? Scenarios.DragOnlyTennis() : Scenarios.VacuumTennis();
            _integrator = Method switch
            {
                "dp54" => DormandPrince54.Instance,
                "stable-rk4" => StableIntegrator.RungeKutta4,
                _ => Integrators.FromName(Method),
            };
            _start = Scenarios.TennisDrive();
        }

        [Benchmark(OperationsPerInvoke = Steps)]
        public double Step()
        {
            FlightModel model = _model;
            IIntegrator integrator = _integrator;
            FlightState state = _start;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 0; i < Steps; i++)
            {
                state = integrator.Step(model, state, derivative, 1.0 / 240, out StateDerivative end, out _);
                derivative = end;
            }

            return state.Position.X;
        }
    }

    /// <summary>
    /// MagnusBall's RK4 against MathNet.Numerics' RungeKutta.FourthOrder and the thesis-style code, on the same ODE (the
    /// thesis's constant-coefficient tennis model, constant spin) and the same 480 steps of 1/240 s.
    /// </summary>
    [Config(typeof(ShortConfig))]
    public class Peers
    {
        public const int Steps = 480;
        private FlightModel _model = null!;
        private FlightState _start;
        private MathNetPeer _mathNet = null!;
        private Vector<double> _mathNetStart = null!;
        private ThesisStyleBall _thesis = null!;
        private double[] _thesisStart = null!;

        [GlobalSetup]
        public void Setup()
        {
            _model = Scenarios.ThesisTennis();
            _start = Scenarios.TennisDrive();
            Vector3d w = _start.AngularVelocity, v = _start.Velocity, p = _start.Position;
            _mathNet = new MathNetPeer(Ball.Tennis.Mass, Ball.Tennis.Radius, 1.21, 0.55, 0.175, Gravity.Standard, w.X, w.Y, w.Z);
            _mathNetStart = Vector<double>.Build.Dense(new[] { p.X, v.X, p.Y, v.Y, p.Z, v.Z });
            _thesisStart = new[] { p.X, v.X, p.Y, v.Y, p.Z, v.Z };
            _thesis = new ThesisStyleBall(Ball.Tennis.Mass, Ball.Tennis.Radius, 1.21, 0.55, 0.175, Gravity.Standard, _thesisStart, w.X, w.Y, w.Z);
        }

        [Benchmark(Baseline = true, OperationsPerInvoke = Steps, Description = "MagnusBall RK4")]
        public double MagnusBallRk4()
        {
            FlightModel model = _model;
            FlightState state = _start;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 0; i < Steps; i++)
            {
                state = ((IIntegrator)RungeKutta4.Instance).Step(model, state, derivative, 1.0 / 240, out StateDerivative end, out _);
                derivative = end;
            }

            return state.Position.X;
        }

        [Benchmark(OperationsPerInvoke = Steps, Description = "MathNet RungeKutta.FourthOrder")]
        public double MathNet() => _mathNet.Solve(_mathNetStart, Steps / 240.0, Steps)[0];

        [Benchmark(OperationsPerInvoke = Steps, Description = "thesis-style double[] RK4")]
        public double ThesisStyle()
        {
            _thesis.Reset(_thesisStart);
            for (int i = 0; i < Steps; i++)
            {
                _thesis.Update(1.0 / 240);
            }

            return _thesis.State[0];
        }
    }

    /// <summary>
    /// A full predicted shot: 2 s at 1/240 s through the queries' TrajectoryPredictor, with its default events (landing on
    /// the ground and the apex, located on each step's cubic Hermite), samples and events written to caller buffers.
    /// </summary>
    [Config(typeof(ShortConfig))]
    public class PredictedShot
    {
        private TrajectoryPredictor _rk4 = null!;
        private TrajectoryPredictor _stableRk4 = null!;
        private FlightModel _model = null!;
        private FlightState _start;
        private FlightState[] _samples = null!;
        private FlightEvent[] _events = null!;
        private readonly DormandPrince54 _dp54 = new DormandPrince54(1e-6, 1e-6);
        private FlightStepper _dp54Stepper = null!;

        [GlobalSetup]
        public void Setup()
        {
            _model = Scenarios.FullTennis();
            _rk4 = new TrajectoryPredictor(_model, RungeKutta4.Instance, 1.0 / 240);
            _dp54Stepper = Flight.ReferenceStepper(_model);
            _stableRk4 = new TrajectoryPredictor(_model, StableIntegrator.RungeKutta4, 1.0 / 240);
            _start = Scenarios.TennisDrive();
            _samples = new FlightState[600];
            _events = new FlightEvent[16];
        }

        [Benchmark(Description = "predict 2 s, RK4 1/240 s, events (480 steps)")]
        public double PredictRk4() => _rk4.Predict(_start, 2.0, _samples, _events, FlightEventKinds.None).EndState.Position.X;

        [Benchmark(Description = "predict 2 s, stable RK4 1/240 s, events (480 steps)")]
        public double PredictStableRk4() => _stableRk4.Predict(_start, 2.0, _samples, _events, FlightEventKinds.None).EndState.Position.X;

        [Benchmark(Description = "DP54 adaptive rtol=atol=1e-6 to the landing, dense-output landing")]
        public double PredictDp54()
        {
            Flight.TryLandReference(_dp54Stepper, _start, 2.0, _dp54, out Vector3d landing, out _);
            return landing.X;
        }
    }

    /// <summary>
    /// Each aim solve of the queries' AimSolver once in its fixed-step mode (RK4 at 1/240 s trial flights; the adaptive solver is in PeerShots and the ratios mode), full tennis model, Cross 2011's court:
    /// launch from 1 m, net 0.914 m high 11.885 m away, baseline 23.77 m away, 30 m/s, 20 rev/s topspin).
    /// </summary>
    [Config(typeof(ShortConfig))]
    public class AimSolves
    {
        private AimSolver _solver = null!;
        private Vector3d _position;
        private LaunchSpin _spin;
        private Plane _net;
        private Vector3d _baseline;
        private Vector3d _corner;

        [GlobalSetup]
        public void Setup()
        {
            FlightModel model = Scenarios.FullTennis();
            _solver = new AimSolver(model, RungeKutta4.Instance, 1.0 / 240, Plane.Ground(model));
            _position = new Vector3d(0, 0, 1);
            _spin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            _net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            _baseline = new Vector3d(23.77, 0, 0);
            _corner = new Vector3d(23.77, 4.1, 0);
        }

        [Benchmark(Description = "MinimumElevationToClear (net)")]
        public double ClearNet() => _solver.MinimumElevationToClear(_position, 30, 0, _spin, _net, 0.914).ElevationRadians;

        [Benchmark(Description = "ElevationToReach (baseline)")]
        public double ReachBaseline() => _solver.ElevationToReach(_position, 30, _spin, _baseline).ElevationRadians;

        [Benchmark(Description = "AnglesToReach (corner)")]
        public double ReachCorner() => _solver.AnglesToReach(_position, 30, _spin, _corner).ElevationRadians;

        [Benchmark(Description = "SpeedToReach (baseline at 8 deg)")]
        public double SpeedToBaseline() => _solver.SpeedToReach(_position, 8 * Math.PI / 180, 0, _spin, _baseline).Speed;
    }

    /// <summary>
    /// Issue 39's aiming as a player thinks, with the adaptive AimSolver and its default work budgets (full tennis model,
    /// Cross 2011's court, 30 m/s, 20 rev/s topspin; golf preset for the club): an ordinary aim solve, the lob, the lob over a
    /// wall the drive hits, a target out of reach, and SwingAim's club inverse to a 170 m flag reached (40 m/s) and out of
    /// reach (37 m/s). The same workloads as the ratios mode's last five rows.
    /// </summary>
    [Config(typeof(ShortConfig))]
    public class AimBudget
    {
        private readonly Workloads _work = new Workloads();

        [GlobalSetup]
        public void Setup() => _work.Setup();

        [Benchmark(Baseline = true, Description = "AnglesToReach (corner)")]
        public double Corner() => _work.AimCorner();

        [Benchmark(Description = "AnglesToReach (corner), the lob")]
        public double Lob() => _work.AimCornerLob();

        [Benchmark(Description = "AnglesToReach (corner) over a 3 m wall")]
        public double OverWall() => _work.AimCornerOverWall();

        [Benchmark(Description = "AnglesToReach, out of reach")]
        public double Unreachable() => _work.AimUnreachable();

        [Benchmark(Description = "SwingAim.ClubFaceToReach, 170 m flag")]
        public double Club() => _work.SwingClub();

        [Benchmark(Description = "SwingAim.ClubFaceToReach, out of reach")]
        public double ClubUnreachable() => _work.SwingClubUnreachable();
    }

    /// <summary>1,000 balls through one 60 FPS frame: four fixed steps of 1/240 s each, full tennis model.</summary>
    [Config(typeof(ShortConfig))]
    public class Frame
    {
        public const int BallCount = 1000;
        private FlightModel _model = null!;
        private FlightState[] _states = null!;
        private StateDerivative[] _derivatives = null!;
        private FlightState[] _starts = null!;

        [Params("rk4", "stable-rk4", "semi-implicit-euler", "rk4 on 2 threads")]
        public string Method { get; set; } = "rk4";

        private IIntegrator _integrator = null!;
        private Action<int> _half = null!;

        [GlobalSetup]
        public void Setup()
        {
            _model = Scenarios.FullTennis();
            _integrator = Method == "stable-rk4" ? StableIntegrator.RungeKutta4 : Method == "rk4 on 2 threads" ? RungeKutta4.Instance : Integrators.FromName(Method);
            _half = part => Advance(part * BallCount / 2, (part + 1) * BallCount / 2);
            var random = new Random(1);
            _starts = new FlightState[BallCount];
            _states = new FlightState[BallCount];
            _derivatives = new StateDerivative[BallCount];
            for (int i = 0; i < BallCount; i++)
            {
                _starts[i] = Scenarios.Launch(1 + random.NextDouble(), 15 + 30 * random.NextDouble(), 20 * random.NextDouble() - 5,
                    Spin.FromRpm(3000 * random.NextDouble() - 1000), Spin.FromRpm(1000 * random.NextDouble() - 500));
            }

            Reset();
        }

        // Each call advances every ball one more frame; balls that pass the ground plane fly on below it at the same cost.
        private void Reset()
        {
            for (int i = 0; i < BallCount; i++)
            {
                _states[i] = _starts[i];
                _derivatives[i] = _model.Derivative(_starts[i]);
            }
        }

        [Benchmark(Description = "1,000 balls x one 60 FPS frame (4 steps of 1/240 s)")]
        public void OneFrame()
        {
            if (Method == "rk4 on 2 threads")
            {
                // The balls are independent: one half per core (Parallel.For allocates a little per call).
                System.Threading.Tasks.Parallel.For(0, 2, _half);
            }
            else
            {
                Advance(0, BallCount);
            }
        }

        private void Advance(int from, int to)
        {
            FlightModel model = _model;
            IIntegrator integrator = _integrator;
            FlightState[] states = _states;
            StateDerivative[] derivatives = _derivatives;
            for (int step = 0; step < 4; step++)
            {
                for (int i = from; i < to; i++)
                {
                    states[i] = integrator.Step(model, states[i], derivatives[i], 1.0 / 240, out StateDerivative end, out _);
                    derivatives[i] = end;
                }
            }
        }
    }
}
