using System;
using System.Collections.Generic;
using System.Diagnostics;
using MagnusBall.Aerodynamics;
using MagnusBall.Batch;
using MagnusBall.Contact;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Stepping;

namespace MagnusBall.Fuzz
{
    /// <summary>
    /// Seeded hostile calls into the library's public types that hold mutable state (issue 15): FlightStepper (Reset,
    /// SetState, TryStep, TryStepAdaptive, StateAt), FixedStepDriver (Reset, Advance with and without an event buffer),
    /// BallBatch (Add, Reset, Clear, Advance, the per-ball getters), TrajectoryPredictor (Predict into reused buffers)
    /// and AimSolver (its four solves), each built with hostile models (presets and random balls, air, laws and gravity
    /// over the whole range of doubles), integrators, event sets and contacts. Before every call the object's observable
    /// state (and the caller's buffers) is snapshotted bit for bit; after a call that throws it must be unchanged, the
    /// exception must be one the member documents (an ArgumentException naming its parameter, or the documented
    /// InvalidOperationException), a call with finite input must leave no NaN (and no non-finite state) behind, and no
    /// call may run 10 s. Shared by the suite's short test and the benchmark project's long run (fuzz mode).
    /// </summary>
    public sealed partial class StatefulFuzz
    {
        /// <summary>The wall-clock time above which a call counts as a hang: 10 s (issue 15's threshold).</summary>
        public static readonly TimeSpan HangThreshold = TimeSpan.FromSeconds(10);

        private readonly Random _random;
        private readonly List<long> _before = new List<long>(4096);
        private readonly List<long> _after = new List<long>(4096);
        private readonly FlightState[] _states = new FlightState[64];
        private readonly Vector3d[] _positions = new Vector3d[64];
        private readonly FlightEvent[] _events = new FlightEvent[16];

        /// <summary>Creates the generator; the same seed gives the same calls.</summary>
        public StatefulFuzz(int seed) => _random = new Random(seed);

        /// <summary>Calls made; calls that threw (documented); calls per type (FlightStepper, FixedStepDriver, BallBatch, TrajectoryPredictor, AimSolver, constructors).</summary>
        public long Calls, Throws, StepperCalls, DriverCalls, BatchCalls, PredictorCalls, AimCalls, ConstructorCalls;

        /// <summary>Defects: state changed by a throwing call, undocumented exceptions, ArgumentExceptions without a parameter name (or, for the aim solves, naming one the call does not have), NaN or non-finite state after finite input, calls over 10 s.</summary>
        public long ChangedAfterThrow, UndocumentedExceptions, UnnamedArgumentErrors, NaNs, NonFiniteStates, Hangs;

        /// <summary>The slowest call and what it was.</summary>
        public TimeSpan Slowest;

        /// <summary>What the slowest call was.</summary>
        public string SlowestCall = string.Empty;

        /// <summary>The first defect seen, for the message.</summary>
        public string? FirstFailure;

        /// <summary>The call running now (for a watchdog on another thread to name a call that does not return).</summary>
        public volatile Func<string> Current = () => string.Empty;

        /// <summary>Wall-clock time spent in the calls of each type (FlightStepper, FixedStepDriver, BallBatch, TrajectoryPredictor, AimSolver).</summary>
        public readonly TimeSpan[] TimeByType = new TimeSpan[5];

        /// <summary>The first failure of each kind (changed after a throw, undocumented exception, unnamed, NaN, non-finite, hang).</summary>
        public readonly Dictionary<string, string> FirstByKind = new Dictionary<string, string>();

        private int _type;

        /// <summary>The defects found (the sum of the defect counters; with shapes, the tunnelling ones too).</summary>
        public long Defects => ChangedAfterThrow + UndocumentedExceptions + UnnamedArgumentErrors + NaNs + NonFiniteStates + Hangs + Penetrations;

        /// <summary>Runs at least <paramref name="count"/> calls: objects are built and then called a random number of times each.</summary>
        public void Run(long count)
        {
            while (Calls < count)
            {
                int kind = _random.Next(10);
                switch (kind)
                {
                    case 0:
                    case 1:
                    case 2:
                        FuzzStepper(count);
                        break;
                    case 3:
                    case 4:
                    case 5:
                        FuzzDriver(count);
                        break;
                    case 6:
                    case 7:
                        FuzzBatch(count);
                        break;
                    case 8:
                        FuzzPredictor(count);
                        break;
                    default:
                        FuzzAim(count);
                        break;
                }
            }
        }

        // ---- FlightStepper ----

        private void FuzzStepper(long count)
        {
            _type = 0;
            FlightModel? model = Model();
            IIntegrator integrator = Integrator();
            FlightEventSet? events = Events(model);
            GroundContact? contact = null;
            if (_random.Next(2) == 0)
            {
                contact = Construct(() => new GroundContact(Bounce(), RandomPlane(), Number(true, positive: true), Number(true, positive: true)), "GroundContact");
            }

            FlightStepper? stepper = model == null ? null : Construct(() => new FlightStepper(model, integrator, events, contact), "FlightStepper");
            if (stepper == null)
            {
                return;
            }

            int calls = 1 + _random.Next(40);
            bool moderate = _random.Next(2) == 0;
            var adaptive = new DormandPrince54(Math.Pow(10, -12 + 11 * _random.NextDouble()), Math.Pow(10, -15 + 14 * _random.NextDouble()));
            for (int c = 0; c < calls && Calls < count; c++)
            {
                StepperCalls++;
                int op = _random.Next(10);
                FlightState state = State(moderate);
                double step = Step(moderate);
                FlightEventKinds stopAt = (FlightEventKinds)_random.Next(64);
                double time = stepper.PreviousState.Time + (stepper.State.Time - stepper.PreviousState.Time) * _random.NextDouble();
                switch (op)
                {
                    case 0:
                        Call(() => SnapStepper(stepper), () => stepper.Reset(state), Finite(state), () => $"FlightStepper({model}, {integrator.Name}).Reset({state})", invalidOperation: false);
                        break;
                    case 1:
                        Call(() => SnapStepper(stepper), () => stepper.SetState(state), Finite(state), () => $"FlightStepper({model}, {integrator.Name}, contact {contact?.Plane.Normal}).SetState({state}) -> {stepper.State} d {stepper.Derivative.Acceleration} {stepper.Derivative.AngularAcceleration}, {stepper.Phase}", invalidOperation: false);
                        break;
                    case 2:
                        Call(() => SnapStepper(stepper), () => stepper.StateAt(time), true, () => $"FlightStepper.StateAt({time:R})", invalidOperation: false, result: s => Add(_after, s));
                        break;
                    case 3:
                        Call(() => SnapStepper(stepper), () => stepper.TryStepAdaptive(adaptive, step, stopAt), double.IsFinite(step),
                            () => $"FlightStepper({model}, contact {contact != null}).TryStepAdaptive(rtol {adaptive.RelativeTolerance:R}, {step:R}, {stopAt}) from {stepper.State}", invalidOperation: true);
                        break;
                    default:
                        Call(() => SnapStepper(stepper), () => stepper.TryStep(step, stopAt), double.IsFinite(step),
                            () => $"FlightStepper({model}, {integrator.Name}, contact {contact != null}).TryStep({step:R}, {stopAt}) from {stepper.State}", invalidOperation: true);
                        break;
                }
            }
        }

        private void SnapStepper(FlightStepper s)
        {
            var list = _after;
            Add(list, s.State);
            Add(list, s.Derivative);
            Add(list, s.PreviousState);
            list.Add((long)s.Phase);
            list.Add(s.IsStopped ? 1 : 0);
            Add(list, s.LastSegment);
            Add(list, s.StopEvent);
            list.Add(s.StepCount);
            list.Add(s.BounceCount);
            list.Add(s.DerivativeEvaluations);
            foreach (FlightEvent e in s.Events.ToArray())
            {
                Add(list, e);
            }
        }

        // ---- FixedStepDriver ----

        private void FuzzDriver(long count)
        {
            _type = 1;
            FlightModel? model = Model();
            if (model == null)
            {
                return;
            }

            bool moderate = _random.Next(2) == 0;
            IIntegrator integrator = Integrator();
            FlightEventSet? events = _random.Next(3) == 0 ? null : Events(model);
            IBounceModel? bounce = _random.Next(2) == 0 ? Bounce() : null;
            double step = Step(moderate || _random.Next(16) != 0); // a hostile fixed step makes most Advance calls run to the work cap
            FlightState start = State(moderate);
            double clamp = _random.Next(3) == 0 ? Number(false, positive: true) : 0.25;
            int maxSteps = _random.Next(3) == 0 ? _random.Next(-2, int.MaxValue) : 0;
            FixedStepDriver? driver = Construct(
                () => _random.Next(4) == 0
                    ? new FixedStepDriver(model, step, start, events, bounce)
                    : new FixedStepDriver(model, integrator, step, start, events, bounce, clamp, maxSteps, Number(true, positive: true), Number(true, positive: true)),
                "FixedStepDriver");
            if (driver == null)
            {
                return;
            }

            int calls = 1 + _random.Next(60);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                DriverCalls++;
                int op = _random.Next(12);
                if (op == 0)
                {
                    FlightState state = State(moderate);
                    Call(() => SnapDriver(driver), () => driver.Reset(state), Finite(state), () => $"FixedStepDriver.Reset({state})", invalidOperation: false);
                    continue;
                }

                double dt = op <= 8 ? _random.NextDouble() * (1.0 / 30) : Number(moderate, positive: _random.Next(8) != 0);
                int length = _random.Next(_events.Length + 1);
                Fill(_events);
                Call(() => { SnapDriver(driver); SnapEvents(); }, () => driver.Advance(dt, _events.AsSpan(0, length)), double.IsFinite(dt),
                    () => $"FixedStepDriver({model}, {driver.Integrator.Name}, step {driver.FixedStep:R}, max {driver.MaxStepsPerAdvance}, bounce {bounce != null}).Advance({dt:R}) from {driver.State}",
                    invalidOperation: false);
            }
        }

        private void SnapDriver(FixedStepDriver d)
        {
            var list = _after;
            Add(list, d.State);
            Add(list, d.PreviousState);
            Add(list, d.RenderState);
            Add(list, d.Accumulator);
            Add(list, d.Alpha);
            list.Add((long)d.Phase);
            list.Add(d.IsFinished ? 1 : 0);
            list.Add(d.Diverged ? 1 : 0);
            list.Add(d.TotalSteps);
            list.Add(d.Bounces);
            list.Add(d.DerivativeEvaluations);
        }

        // ---- BallBatch ----

        private void FuzzBatch(long count)
        {
            _type = 2;
            FlightModel? model = Model();
            if (model == null)
            {
                return;
            }

            bool moderate = _random.Next(2) == 0;
            int capacity = _random.Next(20) == 0 ? _random.Next(-5, 3) : 1 + _random.Next(24);
            Plane? ground = _random.Next(3) == 0 ? RandomPlane() : null;
            BallBatch? batch = Construct(() => new BallBatch(model, capacity, ground), "BallBatch");
            if (batch == null)
            {
                return;
            }

            int calls = 1 + _random.Next(60);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                BatchCalls++;
                int op = _random.Next(12);
                int index = _random.Next(-1, batch.Count + 2);
                FlightState state = State(moderate);
                switch (op)
                {
                    case 0:
                    case 1:
                    case 2:
                        Call(() => SnapBatch(batch), () => batch.Add(state), Finite(state), () => $"BallBatch.Add({state})", invalidOperation: true);
                        break;
                    case 3:
                        Call(() => SnapBatch(batch), () => batch.Reset(index, state), Finite(state), () => $"BallBatch.Reset({index}, {state})", invalidOperation: false);
                        break;
                    case 4:
                        if (_random.Next(4) == 0)
                        {
                            Call(() => SnapBatch(batch), () => batch.Clear(), true, () => "BallBatch.Clear()", invalidOperation: false);
                        }

                        break;
                    case 5:
                        Call(() => SnapBatch(batch), () => batch.TryGetLanding(index, out FlightState _), true, () => $"BallBatch.TryGetLanding({index})", invalidOperation: false);
                        break;
                    case 6:
                        Call(() => SnapBatch(batch), () => batch.GetState(index), true, () => $"BallBatch.GetState({index})", invalidOperation: false);
                        break;
                    default:
                    {
                        double step = Step(moderate || _random.Next(2) == 0);
                        // Steps per call: mostly a frame's worth, now and then up to the documented 1,000,000 (and beyond).
                        int steps = _random.Next(100) == 0 ? _random.Next(-2, 1_000_003) : _random.Next(0, 9);
                        if (steps > 1000 && (long)steps * batch.Count > 1_000_000)
                        {
                            steps = Math.Max(1000, 1_000_000 / Math.Max(1, batch.Count)); // the work of a call is the caller's: count x balls
                        }

                        Call(() => SnapBatch(batch), () => batch.Advance(step, steps), double.IsFinite(step), () => $"BallBatch({model}, {batch.Count} balls).Advance({step:R}, {steps})", invalidOperation: false);
                        break;
                    }
                }
            }
        }

        private void SnapBatch(BallBatch b)
        {
            var list = _after;
            list.Add(b.Count);
            for (int i = 0; i < b.Count; i++)
            {
                Add(list, b.GetState(i));
                list.Add(b.IsFlying(i) ? 1 : 0);
                list.Add(b.HasDiverged(i) ? 1 : 0);
                list.Add(b.TryGetLanding(i, out FlightState landing) ? 1 : 0);
                Add(list, landing);
            }
        }

        // ---- TrajectoryPredictor (reused buffers) ----

        private void FuzzPredictor(long count)
        {
            _type = 3;
            FlightModel? model = Model();
            if (model == null)
            {
                return;
            }

            bool moderate = _random.Next(2) == 0;
            IIntegrator integrator = Integrator();
            double step = Step(moderate || _random.Next(2) == 0);
            FlightEventSet? events = _random.Next(3) == 0 ? null : Events(model);
            TrajectoryPredictor? predictor = Construct(() => new TrajectoryPredictor(model, integrator, step, events), "TrajectoryPredictor");
            if (predictor == null)
            {
                return;
            }

            int calls = 1 + _random.Next(10);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                PredictorCalls++;
                FlightState start = State(moderate);
                double duration = _random.Next(10) == 0 ? Number(moderate, positive: _random.Next(8) != 0) : 10 * _random.NextDouble();
                int length = _random.Next(_states.Length + 1);
                FlightEventKinds stopAt = (FlightEventKinds)_random.Next(64);
                Fill(_states);
                Fill(_positions);
                Fill(_events);
                Prediction p = default;
                Func<string> what = () => $"TrajectoryPredictor({model}, {integrator.Name}, {step:R}).Predict({start}, {duration:R}, {stopAt})";
                if (_random.Next(2) == 0)
                {
                    Call(SnapBuffers, () => p = predictor.Predict(start, duration, _positions.AsSpan(0, length), stopAt), Finite(start) && double.IsFinite(duration), what,
                        invalidOperation: false, result: _ => AddPrediction(p, positions: true));
                }
                else
                {
                    int eventLength = _random.Next(_events.Length + 1);
                    Call(SnapBuffers, () => p = predictor.Predict(start, duration, _states.AsSpan(0, length), _events.AsSpan(0, eventLength), stopAt),
                        Finite(start) && double.IsFinite(duration), what, invalidOperation: false, result: _ => AddPrediction(p, positions: false));
                }
            }
        }

        private void AddPrediction(in Prediction p, bool positions)
        {
            Add(_after, p.EndState);
            if (p.Stopped)
            {
                Add(_after, p.StopEvent);
            }

            for (int i = 0; i < p.SampleCount; i++)
            {
                if (positions)
                {
                    Add(_after, _positions[i]);
                }
                else
                {
                    Add(_after, _states[i]);
                }
            }

            for (int i = 0; i < p.EventCount; i++)
            {
                Add(_after, _events[i]);
            }
        }

        private void SnapBuffers()
        {
            foreach (FlightState s in _states)
            {
                Add(_after, s);
            }

            foreach (Vector3d v in _positions)
            {
                Add(_after, v);
            }

            SnapEvents();
        }

        private void SnapEvents()
        {
            foreach (FlightEvent e in _events)
            {
                Add(_after, e);
            }
        }

        // ---- AimSolver ----

        private void FuzzAim(long count)
        {
            _type = 4;
            FlightModel? model = Model();
            if (model == null)
            {
                return;
            }

            bool moderate = _random.Next(2) == 0;
            IIntegrator integrator = Integrator();
            double step = Step(true);
            double flightTime = _random.Next(4) == 0 ? Number(moderate, positive: true) : 1 + 4 * _random.NextDouble();
            double scan = _random.Next(4) == 0 ? Number(true, positive: true) : 2 + 3 * _random.NextDouble();
            Plane ground = _random.Next(3) == 0 ? RandomPlane() : (model.Up.LengthSquared > 0 ? Plane.Ground(model) : RandomPlane());
            AimSolver? aim = Construct(() => new AimSolver(model, integrator, step, ground, flightTime, -45, 80, scan, Number(true, positive: true) * 30), "AimSolver");
            if (aim == null)
            {
                return;
            }

            int calls = 1 + _random.Next(3);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                AimCalls++;
                Vector3d position = Vector(moderate);
                Vector3d target = Vector(moderate);
                double speed = Number(moderate, positive: true) * 10;
                var spin = new LaunchSpin(Number(moderate), Number(moderate), Number(moderate));
                AimSolution solution = default;
                Func<string> what = () => $"AimSolver({model}, {integrator.Name}, {step:R}, {flightTime:R} s, scan {scan:R}).solve({position}, {speed:R}, {target})";
                int kind = _random.Next(4);
                Action call = kind switch
                {
                    0 => () => solution = aim.ElevationToReach(position, speed, spin, target, Number(true)),
                    1 => () => solution = aim.AnglesToReach(position, speed, spin, target, 45 * _random.NextDouble()),
                    2 => () => solution = aim.SpeedToReach(position, Number(true) % 1.5, Number(true), spin, target),
                    _ => () => solution = aim.MinimumElevationToClear(position, speed, Number(true), spin, RandomPlane(), Number(moderate)),
                };
                // A refusal must name a parameter the solve has (a trial's own "state" leaking out is a defect).
                _parameters = AimParameters[kind];
                Call(() => { }, call, true, what, invalidOperation: false, result: _ =>
                {
                    // Every field of every result (solved, unreachable, at the work cap) finite; the miss may be infinite
                    // (a distance or clearance beyond a double, or an unreachable solve's +infinity), never NaN.
                    Add(_after, solution.Velocity);
                    Add(_after, solution.AngularVelocity);
                    Add(_after, solution.Speed);
                    Add(_after, solution.ElevationRadians);
                    Add(_after, solution.AzimuthFromTargetRadians);
                    Add(_after, solution.Arrival);
                    _derivatives.Add(_after.Count);
                    Add(_after, solution.Miss);
                });
                _parameters = null;
            }
        }

        private static readonly string[][] AimParameters =
        {
            new[] { "position", "speed", "spin", "target", "azimuthFromTargetRadians" },
            new[] { "position", "speed", "spin", "target", "maximumAzimuthDegrees" },
            new[] { "position", "elevationRadians", "azimuthFromTargetRadians", "spin", "target" },
            new[] { "position", "speed", "azimuthRadians", "spin", "plane", "height" },
        };

        // The parameters of the call being judged, where the caller knows them (null: any name passes).
        private string[]? _parameters;

        // ---- The judge ----

        private void Call(Action snapshot, Action call, bool finiteInput, Func<string> what, bool invalidOperation, Action<object?>? result = null) =>
            Call<object?>(snapshot, () => { call(); return null; }, finiteInput, what, invalidOperation, result);

        private void Call<T>(Action snapshot, Func<T> call, bool finiteInput, Func<string> what, bool invalidOperation, Action<T>? result = null)
        {
            Calls++;
            Current = what;
            int type = _type;
            _after.Clear();
            _doubles.Clear();
            _derivatives.Clear();
            snapshot();
            _before.Clear();
            _before.AddRange(_after);
            var clock = Stopwatch.StartNew();
            Exception? thrown = null;
            T value = default!;
            try
            {
                value = call();
            }
            catch (Exception e)
            {
                thrown = e;
            }

            TimeSpan time = clock.Elapsed;
            TimeByType[type] += time;
            if (time > Slowest)
            {
                Slowest = time;
                SlowestCall = what();
            }

            if (time > HangThreshold)
            {
                Hangs++;
                Fail("hang", $"{what()}: ran {time.TotalSeconds:F1} s");
            }

            _after.Clear();
            _doubles.Clear();
            _derivatives.Clear();
            snapshot();
            if (thrown != null)
            {
                Throws++;
                Judge(thrown, what, invalidOperation);
                if (!Same(_before, _after))
                {
                    ChangedAfterThrow++;
                    Fail("changed", $"{what()}: threw {thrown.GetType().Name} ({thrown.Message}) and changed the object's state");
                }

                return;
            }

            if (!finiteInput)
            {
                return;
            }

            result?.Invoke(value);
            Inspect(what);
        }

        private T? Construct<T>(Func<T> create, string what)
            where T : class
        {
            Calls++;
            ConstructorCalls++;
            try
            {
                return create();
            }
            catch (Exception e)
            {
                Throws++;
                Judge(e, () => "new " + what, invalidOperation: false);
                return null;
            }
        }

        private void Judge(Exception e, Func<string> what, bool invalidOperation)
        {
            if (e is ArgumentException a)
            {
                if (string.IsNullOrEmpty(a.ParamName))
                {
                    UnnamedArgumentErrors++;
                    Fail("unnamed", $"{what()}: ArgumentException without a parameter name: {a.Message}");
                }
                else if (_parameters != null && Array.IndexOf(_parameters, a.ParamName) < 0)
                {
                    UnnamedArgumentErrors++; // counted with the unnamed: the caller cannot tell which argument was wrong
                    Fail("misnamed", $"{what()}: ArgumentException naming '{a.ParamName}', which the call does not have: {a.Message}");
                }
            }
            else if (!(invalidOperation && e is InvalidOperationException))
            {
                UndocumentedExceptions++;
                Fail("undocumented", $"{what()}: {e.GetType().Name}: {e.Message}\n{e.StackTrace}");
            }
        }

        // After a call with finite input: every double of the snapshot (states, times, the accumulator) finite, none NaN.
        private void Inspect(Func<string> what)
        {
            for (int i = 0; i < _after.Count; i++)
            {
                if (!_doubles.Contains(i))
                {
                    continue;
                }

                double d = BitConverter.Int64BitsToDouble(_after[i]);
                if (double.IsNaN(d))
                {
                    NaNs++;
                    Fail("NaN", $"{what()}: NaN in the state after the call");
                    return;
                }

                if (double.IsInfinity(d) && !_derivatives.Contains(i))
                {
                    NonFiniteStates++;
                    Fail("non-finite", $"{what()}: an infinite value in the state after the call");
                    return;
                }
            }
        }

        private void Fail(string kind, string message)
        {
            FirstFailure ??= message;
            if (!FirstByKind.ContainsKey(kind))
            {
                FirstByKind[kind] = message;
            }
        }

        private static bool Same(List<long> a, List<long> b)
        {
            if (a.Count != b.Count)
            {
                return false;
            }

            for (int i = 0; i < a.Count; i++)
            {
                if (a[i] != b[i])
                {
                    return false;
                }
            }

            return true;
        }

        // Which entries of _after are doubles (the rest are counts and flags), and which of those are derivatives (which
        // may be infinite where the true force exceeds double.MaxValue, docs/physics.md; never NaN); reset with _after.
        private readonly HashSet<int> _doubles = new HashSet<int>();
        private readonly HashSet<int> _derivatives = new HashSet<int>();

        private void Add(List<long> list, double d)
        {
            if (ReferenceEquals(list, _after))
            {
                _doubles.Add(list.Count);
            }

            list.Add(BitConverter.DoubleToInt64Bits(d));
        }

        private void Add(List<long> list, in Vector3d v)
        {
            Add(list, v.X);
            Add(list, v.Y);
            Add(list, v.Z);
        }

        private void Add(List<long> list, in FlightState s)
        {
            Add(list, s.Position);
            Add(list, s.Velocity);
            Add(list, s.AngularVelocity);
            Add(list, s.Time);
        }

        private void Add(List<long> list, in StateDerivative d)
        {
            int first = list.Count;
            Add(list, d.Velocity);
            Add(list, d.Acceleration);
            Add(list, d.AngularAcceleration);
            if (ReferenceEquals(list, _after))
            {
                for (int i = first; i < list.Count; i++)
                {
                    _derivatives.Add(i);
                }
            }
        }

        private void Add(List<long> list, in HermiteSegment h)
        {
            Add(list, h.Start);
            Add(list, h.StartDerivative);
            Add(list, h.End);
            Add(list, h.EndDerivative);
        }

        private void Add(List<long> list, in FlightEvent e)
        {
            list.Add((long)e.Kind);
            list.Add(e.PlaneIndex);
            Add(list, e.State);
            Add(list, e.After);
            list.Add((long)e.Regime);
            list.Add(e.StartsRolling ? 1 : 0);
        }

        private void Fill(FlightState[] buffer)
        {
            for (int i = 0; i < buffer.Length; i++)
            {
                buffer[i] = new FlightState(new Vector3d(i, -i, 0.5), Vector3d.UnitX, Vector3d.Zero, i);
            }
        }

        private void Fill(Vector3d[] buffer)
        {
            for (int i = 0; i < buffer.Length; i++)
            {
                buffer[i] = new Vector3d(-i, i, 0.25);
            }
        }

        private void Fill(FlightEvent[] buffer)
        {
            for (int i = 0; i < buffer.Length; i++)
            {
                buffer[i] = new FlightEvent(FlightEventKinds.Apex, -1, new FlightState(new Vector3d(i, 0, 0), Vector3d.Zero, Vector3d.Zero, i));
            }
        }

        // ---- Hostile inputs ----

        // A model: half the time a sport preset in hostile air and gravity, else random ball, air and laws; null when a
        // constructor refused (counted as a call).
        private FlightModel? Model()
        {
            bool moderate = _random.Next(2) == 0;
            Vector3d gravity = _random.Next(3) == 0 ? Vector(moderate) : Gravity();
            return Construct<FlightModel>(() =>
            {
                var air = new Air(Math.Abs(Number(moderate)), _random.Next(2) == 0 ? Vector(moderate) : Vector3d.Zero, _random.Next(4) == 0 ? Number(moderate, positive: true) : 1.81e-5);
                if (_random.Next(2) == 0)
                {
                    IReadOnlyList<SportPreset> all = SportPresets.All;
                    return all[_random.Next(all.Count)].CreateModel(air, gravity);
                }

                var ball = new Ball(Number(moderate, positive: true), Number(moderate, positive: true), 0.05 + 0.95 * _random.NextDouble());
                IDragModel? drag = _random.Next(4) switch
                {
                    0 => null,
                    1 => new ConstantDrag(Math.Abs(Number(moderate))),
                    2 => StepanekDrag.Instance,
                    _ => new LinearSpinDrag(Math.Abs(Number(moderate)), Math.Abs(Number(moderate))),
                };
                ILiftModel? lift = _random.Next(4) switch
                {
                    0 => null,
                    1 => new ConstantLift(Number(moderate)),
                    2 => StepanekLift.Instance,
                    _ => new LinearSpinLift(Number(moderate)),
                };
                ISpinDecayModel? decay = _random.Next(3) switch
                {
                    0 => null,
                    1 => new ExponentialSpinDecay(Number(moderate, positive: true)),
                    _ => new SpeedProportionalSpinDecay(Math.Abs(Number(moderate))),
                };
                return new FlightModel(ball, air, gravity, drag, lift, decay);
            }, "FlightModel");
        }

        private Vector3d Gravity() => _random.Next(6) switch
        {
            0 => MagnusBall.Gravity.YUp,
            1 => Vector3d.Zero,
            _ => MagnusBall.Gravity.ZUp,
        };

        private IIntegrator Integrator()
        {
            IIntegrator[] all = Integrators.All;
            return all[_random.Next(all.Length)];
        }

        private FlightEventSet? Events(FlightModel? model)
        {
            if (_random.Next(4) == 0)
            {
                return null;
            }

            Vector3d up = model?.Up ?? Vector3d.UnitZ;
            int planes = _random.Next(4);
            var array = new Plane[planes];
            for (int i = 0; i < planes; i++)
            {
                array[i] = RandomPlane();
            }

            Plane? ground = _random.Next(4) == 0 ? null : (_random.Next(2) == 0 ? RandomPlane() : new Plane(Vector3d.Zero, up.LengthSquared > 0 ? up : Vector3d.UnitZ));
            return Construct(() => new FlightEventSet(_random.Next(5) == 0 ? Vector(false) : up, ground, array), "FlightEventSet");
        }

        private IBounceModel Bounce() => _random.Next(3) switch
        {
            0 => CrossBounce.Hard,
            1 => CrossBounce.Clay,
            _ => CrossBounce.Grass,
        };

        private Plane RandomPlane()
        {
            bool moderate = _random.Next(2) == 0;
            Vector3d normal = _random.Next(3) == 0 ? Vector(moderate) : (_random.Next(2) == 0 ? Vector3d.UnitZ : Vector3d.UnitY);
            Vector3d point = _random.Next(2) == 0 ? Vector3d.Zero : Vector(moderate);
            try
            {
                return new Plane(point, normal);
            }
            catch (ArgumentException e) when (!string.IsNullOrEmpty(e.ParamName))
            {
                // A zero (or vanishing) random normal, refused by Plane's own check: use up instead.
                return new Plane(point, Vector3d.UnitZ);
            }
        }

        private FlightState State(bool moderate)
        {
            if (_random.Next(40) == 0)
            {
                // Now and then a non-finite one, which must be refused.
                return new FlightState(new Vector3d(double.NaN, 0, 0), Vector3d.Zero, Vector3d.Zero, 0);
            }

            if (moderate)
            {
                return new FlightState(
                    new Vector3d(10 * _random.NextDouble(), 10 * _random.NextDouble(), 0.05 + 3 * _random.NextDouble()),
                    Vector(true), Vector(true), _random.Next(4) == 0 ? Number(true) : 0);
            }

            return new FlightState(Vector(false), Vector(false), Vector(false), _random.Next(2) == 0 ? Number(false) : 0);
        }

        // A step: moderate 1e-4 ... 0.1 s; else any finite double, and now and then zero, negative or non-finite.
        private double Step(bool moderate)
        {
            if (_random.Next(30) == 0)
            {
                return _random.Next(4) switch
                {
                    0 => 0,
                    1 => -1.0 / 240,
                    2 => double.NaN,
                    _ => double.PositiveInfinity,
                };
            }

            return moderate ? Math.Pow(10, -4 + 3 * _random.NextDouble()) : Number(false, positive: true);
        }

        private bool Finite(in FlightState s) => s.IsFinite;

        // Moderate: |x| in [1e-3, 1e3] or 0; otherwise log-uniform over all finite doubles with the edges.
        private double Number(bool moderate, bool positive = false)
        {
            double x;
            if (moderate)
            {
                x = _random.Next(10) == 0 ? 0 : Math.Pow(10, -3 + 6 * _random.NextDouble());
            }
            else
            {
                switch (_random.Next(10))
                {
                    case 0:
                        x = 0;
                        break;
                    case 1:
                        x = double.MaxValue;
                        break;
                    case 2:
                        x = double.Epsilon;
                        break;
                    default:
                        double m = Math.Pow(10, -323 + 631 * _random.NextDouble());
                        x = double.IsFinite(m) ? m : double.MaxValue;
                        break;
                }
            }

            if (positive)
            {
                return _random.Next(50) == 0 ? -x : x; // now and then an invalid one
            }

            return _random.Next(2) == 0 ? x : -x;
        }

        private Vector3d Vector(bool moderate) => new Vector3d(Number(moderate), Number(moderate), Number(moderate));
    }
}
