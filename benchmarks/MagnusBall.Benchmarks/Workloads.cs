using System;
using MagnusBall.Batch;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Shots;
using MagnusBall.Stepping;

namespace MagnusBall.Benchmarks
{
    /// <summary>
    /// The workloads issue 11's targets compare, shared by the BenchmarkDotNet class <see cref="PeerShots"/> and the short
    /// "ratios" mode (which also runs under Mono, see docs/performance.md). Each method is one call's work.
    /// </summary>
    internal sealed class Workloads
    {
        public const int ShotSteps = 480;
        public const double Step = 1.0 / 240;

        private ThesisStyleBall _thesis = null!;
        private double[] _thesisStart = null!;
        private ThesisStyleTennisBall _thesisTennis = null!;
        private double[] _thesisTennisStart = null!;
        private FlightModel _thesisModel = null!;
        private FlightModel _fullModel = null!;
        private FlightState _start;
        private TrajectoryPredictor _predictThesis = null!;
        private TrajectoryPredictor _predictFull = null!;
        private FlightState[] _samples = null!;
        private FlightEvent[] _events = null!;
        private BallBatch _batch1000 = null!;
        private BallBatch _batch10000 = null!;
        private FixedStepDriver[] _drivers = null!;
        private FixedStepDriver[] _driversRk4 = null!;
        private FixedStepDriver[] _driversThesis = null!;
        private FlightState[] _kernelStates = null!;
        private StateDerivative[] _kernelDerivatives = null!;
        private AimSolver _solver = null!;
        private AimSolver _solverFixed = null!;
        private SwingAim _club = null!;
        private Vector3d _tee;
        private static readonly LaunchFrame ClubFrame = new LaunchFrame(Scenarios.Up, Vector3d.UnitX);
        private static readonly MagnusBall.Contact.Swings.ClubSwing Club40 = new MagnusBall.Contact.Swings.ClubSwing(40, 12, -2);
        private static readonly MagnusBall.Contact.Swings.ClubSwing Club37 = new MagnusBall.Contact.Swings.ClubSwing(37, 8, -2);
        private LaunchSpin _spin;
        private Plane _net;
        private FlightStepper _courtFlight = null!;
        private FlightStepper _courtFlightTenShapes = null!;

        public void Setup()
        {
            _thesisModel = Scenarios.ThesisTennis();
            _fullModel = Scenarios.FullTennis();
            _start = Scenarios.TennisDrive();
            Vector3d w = _start.AngularVelocity, v = _start.Velocity, p = _start.Position;
            _thesisStart = new[] { p.X, v.X, p.Y, v.Y, p.Z, v.Z };
            _thesis = new ThesisStyleBall(Ball.Tennis.Mass, Ball.Tennis.Radius, 1.21, 0.55, 0.175, Gravity.Standard, _thesisStart, w.X, w.Y, w.Z);
            _thesisTennisStart = ThesisStyleTennisBall.StateOf(_start);
            _thesisTennis = ThesisStyleTennisBall.FullTennis(_thesisTennisStart);
            _predictThesis = new TrajectoryPredictor(_thesisModel, RungeKutta4.Instance, Step);
            _predictFull = new TrajectoryPredictor(_fullModel, RungeKutta4.Instance, Step);
            _samples = new FlightState[600];
            _events = new FlightEvent[16];

            // The crowds fly over a ground 1,000 km down, so each call costs the same (no ball lands during a run: at a tennis
            // ball's terminal speed, about 21 m/s, that is 13 hours of flight; a ground 1 km down was reached within one
            // BenchmarkDotNet run, which then timed landed balls, 6 us for 1,000 drivers): random
            // drives as the Frame benchmark's (15-45 m/s, -5 to 15 degrees, -1000 to 2000 rpm topspin, sidespin).
            var deepGround = new Plane(new Vector3d(0, 0, -1e6), Vector3d.UnitZ);
            _batch1000 = Crowd(1000, deepGround);
            _batch10000 = Crowd(10_000, deepGround);
            var random = new Random(1);
            var events = new FlightEventSet(Scenarios.Up, deepGround);
            _drivers = new FixedStepDriver[1000];
            _driversRk4 = new FixedStepDriver[1000];
            _driversThesis = new FixedStepDriver[1000];
            for (int i = 0; i < _drivers.Length; i++)
            {
                FlightState start = RandomDrive(random);
                _drivers[i] = new FixedStepDriver(_fullModel, Step, start, events);
                _driversRk4[i] = new FixedStepDriver(_fullModel, RungeKutta4.Instance, Step, start, events);
                _driversThesis[i] = new FixedStepDriver(_thesisModel, RungeKutta4.Instance, Step, start, events);
            }

            // The same crowd's states for the kernel-alone floor (RungeKutta4.Advance per ball): 10,000 of them, the first
            // 1,000 for the drivers' floor.
            random = new Random(1);
            _kernelStates = new FlightState[10_000];
            _kernelDerivatives = new StateDerivative[_kernelStates.Length];
            for (int i = 0; i < _kernelStates.Length; i++)
            {
                _kernelStates[i] = RandomDrive(random);
                _kernelDerivatives[i] = _fullModel.Derivative(_kernelStates[i]);
            }

            FlightModel model = _fullModel;
            _solver = new AimSolver(model, Plane.Ground(model)); // adaptive trials (the fast solver)
            _solverFixed = new AimSolver(model, RungeKutta4.Instance, Step, Plane.Ground(model)); // fixed RK4 trials at 1/240 s
            _spin = new LaunchSpin(Spin.FromRevolutionsPerSecond(20));
            _net = new Plane(new Vector3d(11.885, 0, 0), Vector3d.UnitX);
            FlightModel golf = MagnusBall.Presets.SportPresets.Golf.CreateModel(Air.SeaLevel, Scenarios.G);
            _club = new SwingAim(new AimSolver(golf, Plane.Ground(golf), maximumFlightTime: 20)); // adaptive trials, default budgets
            _tee = new Vector3d(0, 0, golf.Ball.Radius);

            // The drive on a court it bounces on (the ground alone), and the same among 21 shapes: the tennis net (two cord
            // halves, twelve mesh pieces, two posts), the two back fences, the two side fences and the umpire's chair (issue 40's cost).
            var court = new GroundContact(CrossBounce.Hard, new Plane(Vector3d.Zero, Vector3d.UnitZ));
            _courtFlight = new FlightStepper(_fullModel, RungeKutta4.Instance, FlightEventSet.ForModel(_fullModel), court);
            var fence = new ContactProperties(0.3, 0.5);
            var shapes = new System.Collections.Generic.List<ContactShape>(SportShapes.TennisNet(0, new Vector3d(11.885, 0, 0), Vector3d.UnitY, Vector3d.UnitZ))
            {
                BoxShape.Rectangle(5, new Vector3d(-6.4, 0, 2), Vector3d.UnitX, Vector3d.UnitY, 18.29, 4, fence),
                BoxShape.Rectangle(6, new Vector3d(30.17, 0, 2), -Vector3d.UnitX, Vector3d.UnitY, 18.29, 4, fence),
                BoxShape.Rectangle(7, new Vector3d(11.885, -9.15, 2), Vector3d.UnitY, Vector3d.UnitX, 36.57, 4, fence),
                BoxShape.Rectangle(8, new Vector3d(11.885, 9.15, 2), -Vector3d.UnitY, Vector3d.UnitX, 36.57, 4, fence),
                new BoxShape(9, new Vector3d(11.885, -7, 1), new Vector3d(0.4, 0.4, 1), Vector3d.UnitX, Vector3d.UnitY, fence),
            };
            _courtFlightTenShapes = new FlightStepper(_fullModel, RungeKutta4.Instance, FlightEventSet.ForModel(_fullModel), court, shapes.ToArray());
        }

        private BallBatch Crowd(int count, Plane ground)
        {
            var random = new Random(1);
            var batch = new BallBatch(_fullModel, count, ground);
            for (int i = 0; i < count; i++)
            {
                batch.Add(RandomDrive(random));
            }

            return batch;
        }

        private static FlightState RandomDrive(Random random) =>
            Scenarios.Launch(1 + random.NextDouble(), 15 + 30 * random.NextDouble(), 20 * random.NextDouble() - 5,
                Spin.FromRpm(3000 * random.NextDouble() - 1000), Spin.FromRpm(1000 * random.NextDouble() - 500));

        /// <summary>The thesis-style code: one 2 s shot, 480 RK4 steps of 1/240 s, no events (the unit of the targets).</summary>
        public double ThesisShot()
        {
            _thesis.Reset(_thesisStart);
            for (int i = 0; i < ShotSteps; i++)
            {
                _thesis.Update(Step);
            }

            return _thesis.State[0];
        }

        /// <summary>
        /// The full tennis model in the thesis's style (<see cref="ThesisStyleTennisBall"/>): one 2 s shot, 480 RK4 steps of
        /// 1/240 s, no events. The naive code a game on the full model replaces; the unit U_full of the full-model rows.
        /// </summary>
        public double ThesisStyleTennisShot()
        {
            _thesisTennis.Reset(_thesisTennisStart);
            for (int i = 0; i < ShotSteps; i++)
            {
                _thesisTennis.Update(Step);
            }

            return _thesisTennis.State[0];
        }

        /// <summary>MagnusBall's RK4 through IIntegrator.Step, 480 steps on the thesis's ODE, as a loop calls it.</summary>
        public double Rk4ThesisShot() => Rk4Shot(_thesisModel);

        /// <summary>The same on the full tennis model.</summary>
        public double Rk4FullShot() => Rk4Shot(_fullModel);

        /// <summary>The 480 steps on the thesis's ODE in one RungeKutta4.Advance call (arguments checked once, no per-step call).</summary>
        public double Rk4ThesisRun()
        {
            FlightState state = _start;
            StateDerivative derivative = _thesisModel.Derivative(state);
            RungeKutta4.Instance.Advance(_thesisModel, ref state, ref derivative, Step, ShotSteps);
            return state.Position.X;
        }

        /// <summary>The 480 steps on the thesis's ODE as 480 calls of RungeKutta4.Advance with count 1 (a game's one step a frame, in place).</summary>
        public double Rk4ThesisAdvanceEach()
        {
            FlightState state = _start;
            StateDerivative derivative = _thesisModel.Derivative(state);
            for (int i = 0; i < ShotSteps; i++)
            {
                RungeKutta4.Instance.Advance(_thesisModel, ref state, ref derivative, Step, 1);
            }

            return state.Position.X;
        }

        private double Rk4Shot(FlightModel model)
        {
            FlightState state = _start;
            StateDerivative derivative = model.Derivative(state);
            for (int i = 0; i < ShotSteps; i++)
            {
                state = ((IIntegrator)RungeKutta4.Instance).Step(model, state, derivative, Step, out StateDerivative end, out _);
                derivative = end;
            }

            return state.Position.X;
        }

        /// <summary>The drive on a court (a GroundContact: it bounces), 2 s of 480 RK4 steps of 1/240 s, the ground alone.</summary>
        public double FlightGround() => FlyCourt(_courtFlight);

        /// <summary>The same among ten contact shapes (the tennis net's five, four fences, the umpire's chair).</summary>
        public double FlightTenShapes() => FlyCourt(_courtFlightTenShapes);

        private double FlyCourt(FlightStepper flight)
        {
            flight.Reset(_start);
            for (int i = 0; i < ShotSteps && !flight.IsStopped; i++)
            {
                flight.TryStep(Step);
            }

            return flight.State.Position.X;
        }

        /// <summary>A 2 s predicted shot (480 RK4 steps) with the landing and apex events, thesis model.</summary>
        public double PredictThesis() => _predictThesis.Predict(_start, 2.0, _samples, _events, FlightEventKinds.None).EndState.Position.X;

        /// <summary>The same on the full tennis model.</summary>
        public double PredictFull() => _predictFull.Predict(_start, 2.0, _samples, _events, FlightEventKinds.None).EndState.Position.X;

        /// <summary>1,000 balls (full tennis model) through one 60 FPS frame: 4 RK4 steps of 1/240 s.</summary>
        public double Batch1000()
        {
            _batch1000.Advance(Step, 4);
            return _batch1000.GetState(0).Position.X;
        }

        /// <summary>10,000 balls through one 60 FPS frame.</summary>
        public double Batch10000()
        {
            _batch10000.Advance(Step, 4);
            return _batch10000.GetState(0).Position.X;
        }

        /// <summary>1,000 balls through one 60 FPS frame, one FixedStepDriver each (its default stable RK4), one at a time.</summary>
        public double Drivers1000() => Drive(_drivers);

        /// <summary>The same with plain RK4 in each driver.</summary>
        public double Drivers1000Rk4() => Drive(_driversRk4);

        /// <summary>
        /// The same with plain RK4 on the thesis model, the model one thesis-style shot flies: the per-step parity the
        /// 8 U target asks for, without the full model's costlier laws.
        /// </summary>
        public double Drivers1000Thesis() => Drive(_driversThesis);

        /// <summary>
        /// The floor of <see cref="Drivers1000Rk4"/>: the same 1,000 balls (full tennis model) through one 60 FPS frame, each
        /// by one RungeKutta4.Advance call of 4 steps, the kernel alone with the state in registers: no stepper, no event test,
        /// no driver. No per-ball loop on this model and method costs less.
        /// </summary>
        public double KernelFloor1000() => KernelFloor(1000);

        /// <summary>
        /// The same for 10,000 balls: the floor of a batch that steps ball by ball (<see cref="Batch10000"/> where
        /// <c>Vector&lt;double&gt;</c> is not accelerated, as under Mono 6.8).
        /// </summary>
        public double KernelFloor10000() => KernelFloor(10_000);

        private double KernelFloor(int count)
        {
            for (int i = 0; i < count; i++)
            {
                RungeKutta4.Instance.Advance(_fullModel, ref _kernelStates[i], ref _kernelDerivatives[i], Step, 4);
            }

            return _kernelStates[0].Position.X;
        }

        private static double Drive(FixedStepDriver[] drivers)
        {
            for (int i = 0; i < drivers.Length; i++)
            {
                drivers[i].Advance(1.0 / 60);
            }

            return drivers[0].State.Position.X;
        }

        /// <summary>AimSolver.MinimumElevationToClear (the net; Cross 2011's court, 30 m/s, 20 rev/s topspin), adaptive trials.</summary>
        public double AimClearNet() => _solver.MinimumElevationToClear(new Vector3d(0, 0, 1), 30, 0, _spin, _net, 0.914).ElevationRadians;

        /// <summary>AimSolver.ElevationToReach (the baseline).</summary>
        public double AimBaseline() => _solver.ElevationToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 0, 0)).ElevationRadians;

        /// <summary>AimSolver.AnglesToReach (a corner 4.1 m aside).</summary>
        public double AimCorner() => _solver.AnglesToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 4.1, 0)).ElevationRadians;

        /// <summary>AimSolver.AnglesToReach (the corner) with fixed RK4 trials at 1/240 s (the solver's other mode).</summary>
        public double AimCornerFixed() => _solverFixed.AnglesToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 4.1, 0)).ElevationRadians;

        /// <summary>AimSolver.ElevationToReach (the baseline) with fixed RK4 trials at 1/240 s.</summary>
        public double AimBaselineFixed() => _solverFixed.ElevationToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 0, 0)).ElevationRadians;

        /// <summary>AimSolver.SpeedToReach (the baseline at 8 degrees).</summary>
        public double AimSpeed() => _solver.SpeedToReach(new Vector3d(0, 0, 1), 8 * Math.PI / 180, 0, _spin, new Vector3d(23.77, 0, 0)).Speed;
    
        /// <summary>AimSolver.AnglesToReach (the corner) asking for the lob (AimArc.High), adaptive trials.</summary>
        public double AimCornerLob() => _solver.AnglesToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 4.1, 0), arc: AimArc.High).ElevationRadians;

        /// <summary>AimSolver.AnglesToReach (the corner) over a 3 m wall at the net: the drive is blocked, the lob clears it.</summary>
        public double AimCornerOverWall() =>
            _solver.AnglesToReach(new Vector3d(0, 0, 1), 30, _spin, new Vector3d(23.77, 4.1, 0), obstacle: new AimObstacle(11.885, 3)).ElevationRadians;

        /// <summary>AimSolver.AnglesToReach out of reach (10 m/s to 60 m): Unreachable.</summary>
        public double AimUnreachable() => _solver.AnglesToReach(new Vector3d(0, 0, 1), 10, _spin, new Vector3d(60, 4, 0)).Miss;

        /// <summary>SwingAim.ClubFaceToReach: a 40 m/s club to a flag 170 m away (golf preset, adaptive trials): solved.</summary>
        public double SwingClub() =>
            _club.ClubFaceToReach(Club40, ClubFrame, _tee, new Vector3d(170, 3, 0)).Swing.DynamicLoftDegrees;

        /// <summary>SwingAim.ClubFaceToReach: a 37 m/s club to the same flag, out of its reach: Unreachable.</summary>
        public double SwingClubUnreachable() =>
            _club.ClubFaceToReach(Club37, ClubFrame, _tee, new Vector3d(170, 3, 0)).Swing.DynamicLoftDegrees;
    }
}
