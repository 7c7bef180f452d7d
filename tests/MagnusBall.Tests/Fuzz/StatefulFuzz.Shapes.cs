using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;
using MagnusBall.Shots;
using MagnusBall.Stepping;

namespace MagnusBall.Fuzz
{
    /// <summary>
    /// Issue 40's contact shapes under the stateful fuzz (<see cref="RunShapes"/>): FlightStepper (Reset, SetState, TryStep,
    /// TryStepAdaptive, StateAt), FixedStepDriver (Reset, Advance) and TrajectoryPredictor (Predict) built with 1-8 random shapes of
    /// every kind (boxes, thin boxes and rectangles, capsules, cylinders, spheres, tori, net meshes, and the SportShapes fixtures;
    /// sizes from millimetres to tens of metres, random orientations, contact parameters over their ranges, fixed and light
    /// effective masses), with and without a ground contact, presets and random balls, and random valid states aimed at the shapes
    /// (touching them, just inside them, settling slowly on them, fast up to 150 m/s) and steps from 1e-5 s to 5 s; now and then
    /// hostile arguments. Judged as the rest of the stateful fuzz (documented exceptions only, state unchanged after a throw, no
    /// NaN or non-finite state after finite input, no call over 10 s), plus the no-tunnelling invariant: a ball whose centre
    /// starts at least its radius outside a shape is, after every call, never more than <see cref="PenetrationTolerance"/>
    /// deeper into it than touching (centre distance &gt;= radius - tolerance); on a step that is flight only (no rolling before,
    /// after or within it), the same holds at points of the step's dense output read with StateAt.
    /// </summary>
    public sealed partial class StatefulFuzz
    {
        /// <summary>
        /// How far the ball's surface may be found inside a shape it started clear of before it counts as tunnelling: 1 cm + 1e-6 m.
        /// docs/contacts.md's limits: between frames a ball rolling on a curved shape may be off its surface by the tangent plane's
        /// sag (about 1 cm at game speeds and frame steps), and a dip of less than 0.1 micrometre may be missed. 1e-6 m is ten times
        /// that miss; 1 cm is the documented sag. Deeper than this is a ball passing into or through a surface.
        /// </summary>
        public const double PenetrationTolerance = 0.01 + 1e-6;

        /// <summary>A step end found inside a shape by more than this (1e-6 m) is recorded as shallow (reported, not a defect): the
        /// docs say a roll step's end is put back on the surface, and the suite's own flights hold the ball out to 1e-9 m.</summary>
        public const double ShallowTolerance = 1e-6;

        /// <summary>Shape-fuzz calls per type (FlightStepper, FixedStepDriver, TrajectoryPredictor), shape sets built, Contact events seen, checks of the invariant.</summary>
        public long ShapeStepperCalls, ShapeDriverCalls, ShapePredictorCalls, ShapeSets, ShapeContacts, ShapeSettles, PenetrationChecks;

        /// <summary>Defect: the ball found deeper than <see cref="PenetrationTolerance"/> in a shape it started clear of.</summary>
        public long Penetrations;

        /// <summary>Not a defect: a step end deeper than <see cref="ShallowTolerance"/> but within <see cref="PenetrationTolerance"/>.</summary>
        public long ShallowPenetrations;

        /// <summary>Penetrations by the kind of shape (box, rectangle/thin box, capsule, cylinder, sphere, torus, net mesh).</summary>
        public readonly long[] PenetrationsByKind = new long[7];

        /// <summary>The names of the kinds in <see cref="PenetrationsByKind"/>.</summary>
        public static readonly string[] ShapeKindNames = { "box", "thin box/rectangle", "capsule", "cylinder", "sphere", "torus", "net mesh" };

        /// <summary>The deepest penetration seen, m (beyond touching), and where.</summary>
        public double DeepestPenetration;

        /// <summary>Where the deepest penetration was seen (the call log that reproduces it).</summary>
        public string DeepestPenetrationCall = string.Empty;

        /// <summary>Every penetration's repro log, up to 20 (for reducing them).</summary>
        public readonly List<string> PenetrationLogs = new List<string>();

        private readonly StringBuilder _log = new StringBuilder();
        private ContactShape[] _fuzzShapes = Array.Empty<ContactShape>();
        private bool[] _clear = Array.Empty<bool>();
        private double _ballRadius;
        private FlightModel? _checkModel;
        private StableIntegrator? _bound; // the flight's fixed-step method at its stability bound; null for a stable integrator
        private bool _unjudged;           // a fixed step past the bound was taken: positions not judged until a step within it

        /// <summary>Checks skipped because a fixed step went past its method's stability bound (the caller's to refuse: see <see cref="Unstable"/>).</summary>
        public long UnstableSkips;

        // The flight's fixed steps are checked against its method's stability bound (StableIntegrator.AtStabilityBound: a step past it
        // may come out finite and wrong, which the library leaves to the caller to refuse or flag, as the CLI and the playground do);
        // after such a step, the flight's positions are not held to the no-tunnelling invariant until a step within the bound (or a
        // reset), from where the shapes the ball is then clear of are judged again.
        private void Watch(FlightModel model, IIntegrator integrator)
        {
            _checkModel = model;
            _bound = StableIntegrator.AtStabilityBound(integrator);
        }

        private bool Unstable(in FlightState state, double step)
        {
            if (_bound == null || _checkModel == null || !state.IsFinite || !(step > 0) || !double.IsFinite(step) || _bound.SubstepCount(_checkModel, state, step) <= 1)
            {
                return false;
            }

            UnstableSkips++;
            Array.Clear(_clear, 0, _clear.Length);
            _unjudged = true;
            return true;
        }

        // A step within the bound after one past it: judged again from here.
        private void Rearm(in Vector3d position)
        {
            if (_unjudged)
            {
                SetClear(position);
            }
        }

        /// <summary>Runs at least <paramref name="count"/> calls into objects built with contact shapes.</summary>
        public void RunShapes(long count)
        {
            while (Calls < count)
            {
                int kind = _random.Next(10);
                if (kind < 6)
                {
                    FuzzShapeStepper(count);
                }
                else if (kind < 9)
                {
                    FuzzShapeDriver(count);
                }
                else
                {
                    FuzzShapePredictor(count);
                }
            }
        }

        // A model (its code), a method, the up and the shapes (their code) for one object of the shape fuzz, drawn in that order;
        // false where the model or the shapes could not be built (a hostile model's or shape's constructor refused).
        private bool Scene(out FlightModel model, out string modelCode, out IIntegrator integrator, out Vector3d up, out ContactShape[] shapes, out string shapesCode)
        {
            (FlightModel? m, string code) = ShapeModel();
            model = m!;
            modelCode = code;
            integrator = null!;
            up = Vector3d.Zero;
            shapes = null!;
            shapesCode = string.Empty;
            if (m == null)
            {
                return false;
            }

            integrator = Integrator();
            up = m.Up.LengthSquared > 0 ? m.Up : Vector3d.UnitZ;
            ContactShape[]? built = Shapes(m, up, out shapesCode);
            shapes = built!;
            return built != null;
        }

        // The shapes, ball and method the no-tunnelling invariant judges from here.
        private void Judge(FlightModel model, IIntegrator integrator, ContactShape[] shapes)
        {
            _fuzzShapes = shapes;
            _clear = new bool[shapes.Length];
            _ballRadius = model.Ball.Radius;
            Watch(model, integrator);
        }

        // ---- FlightStepper with shapes ----

        private void FuzzShapeStepper(long count)
        {
            _type = 0;
            if (!Scene(out FlightModel model, out string modelCode, out IIntegrator integrator, out Vector3d up, out ContactShape[] shapes, out string shapesCode))
            {
                return;
            }

            GroundContact? ground = null;
            string groundCode = "null";
            if (_random.Next(2) == 0)
            {
                Plane plane = _random.Next(5) == 0 ? new Plane(Vector3d.Zero, up + Unit() * 0.3) : new Plane(Vector3d.Zero, up);
                double rest = _random.Next(4) == 0 ? 2 * _random.NextDouble() : 0.1;
                double rolling = _random.Next(4) == 0 ? _random.NextDouble() : 0.03;
                IBounceModel bounce = Bounce();
                ground = new GroundContact(bounce, plane, rest, rolling);
                groundCode = $"new GroundContact(CrossBounce.{BounceName(bounce)}, new Plane({V(plane.Point)}, {V(plane.Normal)}), {rest:R}, {rolling:R})";
            }

            FlightEventSet? events = null;
            string eventsCode = "null";
            if (_random.Next(3) == 0)
            {
                events = new FlightEventSet(up, new Plane(Vector3d.Zero, up));
                eventsCode = $"new FlightEventSet({V(up)}, new Plane(Vector3d.Zero, {V(up)}))";
            }

            _log.Clear();
            _log.Append($"FlightModel model = {modelCode};\nContactShape[] shapes = {shapesCode};\n");
            _log.Append($"var stepper = new FlightStepper(model, Integrators.FromName(\"{integrator.Name}\"), {eventsCode}, {groundCode}, shapes);\n");
            FlightStepper? stepper = Construct(() => new FlightStepper(model, integrator, events, ground, shapes), "FlightStepper with shapes");
            if (stepper == null)
            {
                return;
            }

            Judge(model, integrator, shapes);
            double rtol = Math.Pow(10, -10 + 8 * _random.NextDouble());
            var adaptive = new DormandPrince54(rtol, rtol * 1e-3);
            bool started = false;
            int calls = 1 + _random.Next(60);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                ShapeStepperCalls++;
                int op = _random.Next(12);
                if (!started || op == 0 || op == 1 || (stepper.IsStopped && _random.Next(2) == 0))
                {
                    FlightState state = ShapeState(model, up, shapes);
                    bool set = started && op == 1;
                    string code = $"stepper.{(set ? "SetState" : "Reset")}({S(state)});";
                    long throws = Throws;
                    Call(() => SnapStepper(stepper), () => { if (set) { stepper.SetState(state); } else { stepper.Reset(state); } }, state.IsFinite,
                        () => _log + code, invalidOperation: false);
                    if (Throws == throws)
                    {
                        _log.Append(code).Append('\n');
                        started = true;
                        SetClear(stepper.State.Position);
                    }

                    continue;
                }

                double step = ShapeStep();
                FlightEventKinds stopAt = _random.Next(4) == 0 ? (FlightEventKinds)_random.Next(64) : FlightEventKinds.None;
                if (op == 2)
                {
                    double time = stepper.PreviousState.Time + (stepper.State.Time - stepper.PreviousState.Time) * (1.2 * _random.NextDouble() - 0.1);
                    if (_random.Next(30) == 0)
                    {
                        time = double.NaN;
                    }

                    Call(() => SnapStepper(stepper), () => stepper.StateAt(time), true, () => _log + $"stepper.StateAt({time:R});", invalidOperation: false, result: s => Add(_after, s));
                    continue;
                }

                bool adapt = op == 3 || op == 4;
                if (started && (adapt || !Unstable(stepper.State, step)))
                {
                    // (An adaptive step controls its error. A rolling ball's step is gated too: where it leaves the surface within
                    // the step, the method flies the rest.)
                    Rearm(stepper.State.Position);
                }

                string stepCode = adapt
                    ? $"stepper.TryStepAdaptive(new DormandPrince54({adaptive.RelativeTolerance:R}, {adaptive.AbsoluteTolerance:R}), {step:R}, (FlightEventKinds){(int)stopAt});"
                    : $"stepper.TryStep({step:R}, (FlightEventKinds){(int)stopAt});";
                FlightPhase before = stepper.Phase;
                long thrown = Throws;
                StepOutcome outcome = default;
                Call(() => SnapStepper(stepper), () => outcome = adapt ? stepper.TryStepAdaptive(adaptive, step, stopAt) : stepper.TryStep(step, stopAt), double.IsFinite(step),
                    () => _log + stepCode, invalidOperation: true);
                if (Throws != thrown)
                {
                    continue;
                }

                _log.Append(stepCode).Append($" // {outcome}, t = {stepper.State.Time:R}, phase {stepper.Phase}\n");
                bool settles = false;
                foreach (FlightEvent e in stepper.Events)
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        ShapeContacts++;
                        if (e.StartsRolling)
                        {
                            ShapeSettles++;
                            settles = true;
                        }
                    }
                }

                CheckClear(stepper.State.Position, stepper.State.Time, endOfStep: true);
                if (before == FlightPhase.Flying && stepper.Phase != FlightPhase.Rolling && !settles && stepper.State.Time > stepper.PreviousState.Time)
                {
                    // Flight only: the dense output itself must stay out (no sag allowance is documented for flight; the tolerance applies anyway).
                    double t0 = stepper.PreviousState.Time, t1 = stepper.State.Time;
                    double speed = Math.Max(stepper.PreviousState.Velocity.Length, stepper.State.Velocity.Length);
                    int samples = (int)Math.Min(64, Math.Max(4, Math.Ceiling(speed * (t1 - t0) / Math.Max(_ballRadius, 1e-3))));
                    for (int i = 1; i < samples; i++)
                    {
                        double t = t0 + (t1 - t0) * i / samples;
                        CheckClear(stepper.StateAt(t).Position, t, endOfStep: false);
                    }
                }
            }
        }

        // ---- FixedStepDriver with shapes ----

        private void FuzzShapeDriver(long count)
        {
            _type = 1;
            if (!Scene(out FlightModel model, out string modelCode, out IIntegrator integrator, out Vector3d up, out ContactShape[] shapes, out string shapesCode))
            {
                return;
            }

            double fixedStep = _random.Next(3) == 0 ? ShapeStep() : 1.0 / (30 + _random.Next(500));
            FlightState start = ShapeState(model, up, shapes);
            bool bounce = _random.Next(2) == 0;
            IBounceModel bounceModel = Bounce();
            FlightEventSet events = new FlightEventSet(up, new Plane(Vector3d.Zero, up));
            _log.Clear();
            _log.Append($"FlightModel model = {modelCode};\nContactShape[] shapes = {shapesCode};\n");
            _log.Append($"var driver = new FixedStepDriver(model, Integrators.FromName(\"{integrator.Name}\"), {fixedStep:R}, {S(start)}, " +
                        $"new FlightEventSet({V(up)}, new Plane(Vector3d.Zero, {V(up)})), {(bounce ? "CrossBounce." + BounceName(bounceModel) : "null")}, shapes: shapes);\n");
            FixedStepDriver? driver = Construct(
                () => new FixedStepDriver(model, integrator, fixedStep, start, events, bounce ? bounceModel : null, shapes: shapes), "FixedStepDriver with shapes");
            if (driver == null)
            {
                return;
            }

            Judge(model, integrator, shapes);
            SetClear(driver.State.Position);
            int calls = 1 + _random.Next(60);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                ShapeDriverCalls++;
                if (_random.Next(15) == 0)
                {
                    FlightState state = ShapeState(model, up, shapes);
                    string code = $"driver.Reset({S(state)});";
                    long throws = Throws;
                    Call(() => SnapDriver(driver), () => driver.Reset(state), state.IsFinite, () => _log + code, invalidOperation: false);
                    if (Throws == throws)
                    {
                        _log.Append(code).Append('\n');
                        SetClear(driver.State.Position);
                    }

                    continue;
                }

                double dt = _random.Next(10) == 0 ? ShapeStep() : _random.NextDouble() / 30;
                if (_random.Next(40) == 0)
                {
                    dt = -dt;
                }

                int length = _random.Next(_events.Length + 1);
                Fill(_events);
                string advance = $"driver.Advance({dt:R}, new FlightEvent[{length}]);";
                if (!Unstable(driver.State, fixedStep))
                {
                    Rearm(driver.State.Position);
                }
                long thrown = Throws;
                Call(() => { SnapDriver(driver); SnapEvents(); }, () => driver.Advance(dt, _events.AsSpan(0, length)), true, () => _log + advance, invalidOperation: false);
                if (Throws == thrown)
                {
                    _log.Append(advance).Append($" // t = {driver.State.Time:R}\n");
                    CheckClear(driver.State.Position, driver.State.Time, endOfStep: true);
                }
            }
        }

        // ---- TrajectoryPredictor with shapes ----

        private void FuzzShapePredictor(long count)
        {
            _type = 3;
            if (!Scene(out FlightModel model, out string modelCode, out IIntegrator integrator, out Vector3d up, out ContactShape[] shapes, out string shapesCode))
            {
                return;
            }

            double step = _random.Next(3) == 0 ? ShapeStep() : 1.0 / (30 + _random.Next(500));
            FlightEventSet? events = _random.Next(3) == 0 ? null : new FlightEventSet(up, new Plane(Vector3d.Zero, up));
            _log.Clear();
            _log.Append($"FlightModel model = {modelCode};\nContactShape[] shapes = {shapesCode};\n");
            _log.Append($"var predictor = new TrajectoryPredictor(model, Integrators.FromName(\"{integrator.Name}\"), {step:R}, " +
                        $"{(events == null ? "null" : $"new FlightEventSet({V(up)}, new Plane(Vector3d.Zero, {V(up)}))")}, shapes);\n");
            TrajectoryPredictor? predictor = Construct(() => new TrajectoryPredictor(model, integrator, step, events, shapes), "TrajectoryPredictor with shapes");
            if (predictor == null)
            {
                return;
            }

            Judge(model, integrator, shapes);
            int calls = 1 + _random.Next(6);
            for (int c = 0; c < calls && Calls < count; c++)
            {
                ShapePredictorCalls++;
                FlightState start = ShapeState(model, up, shapes);
                double duration = _random.Next(10) == 0 ? -1 : 5 * _random.NextDouble();
                int length = _random.Next(_states.Length + 1);
                int eventLength = _random.Next(_events.Length + 1);
                FlightEventKinds stopAt = _random.Next(3) == 0 ? (FlightEventKinds)_random.Next(64) : FlightEventKinds.Landing;
                Fill(_states);
                Fill(_positions);
                Fill(_events);
                Prediction p = default;
                string code = $"predictor.Predict({S(start)}, {duration:R}, new FlightState[{length}], new FlightEvent[{eventLength}], (FlightEventKinds){(int)stopAt});";
                long thrown = Throws;
                Call(SnapBuffers, () => p = predictor.Predict(start, duration, _states.AsSpan(0, length), _events.AsSpan(0, eventLength), stopAt),
                    true, () => _log + code, invalidOperation: false, result: _ => AddPrediction(p, positions: false));
                if (Throws != thrown)
                {
                    continue;
                }

                SetClear(start.Position);
                string saved = _log.ToString();
                _log.Append(code).Append('\n');
                for (int i = 0; i < p.SampleCount; i++)
                {
                    CheckClear(_states[i].Position, _states[i].Time, endOfStep: true);
                    if (Unstable(_states[i], step))
                    {
                        break; // the step from this sample is past the bound: the rest of this prediction is not judged
                    }
                }

                if (!p.SamplesTruncated || _bound == null)
                {
                    // (With samples cut short, a step past the stability bound beyond them is not seen: the end is then not judged.)
                    CheckClear(p.EndState.Position, p.EndState.Time, endOfStep: true);
                }
                _log.Clear().Append(saved);
            }
        }

        // ---- The no-tunnelling invariant ----

        private void SetClear(in Vector3d position)
        {
            _unjudged = false;
            for (int i = 0; i < _fuzzShapes.Length; i++)
            {
                _clear[i] = _fuzzShapes[i].SignedDistance(position, out _) >= _ballRadius;
            }
        }

        private void CheckClear(in Vector3d position, double time, bool endOfStep)
        {
            if (!position.IsFinite)
            {
                return; // judged as a non-finite state elsewhere
            }

            for (int i = 0; i < _fuzzShapes.Length; i++)
            {
                if (!_clear[i])
                {
                    continue;
                }

                PenetrationChecks++;
                double depth = _ballRadius - _fuzzShapes[i].SignedDistance(position, out _);
                // Rounding of the positions themselves: 1e-13 of the coordinates' size (tens of metres here: 1e-12 m).
                double rounding = 1e-13 * (Math.Abs(position.X) + Math.Abs(position.Y) + Math.Abs(position.Z));
                if (depth > PenetrationTolerance + rounding)
                {
                    Penetrations++;
                    PenetrationsByKind[Kind(_fuzzShapes[i])]++;
                    _clear[i] = false; // once per shape and flight
                    string message = $"{_log}// at t = {time:R} ({(endOfStep ? "step end" : "StateAt within a flight-only step")}) the ball is {depth:R} m into shapes[{i}] " +
                                     $"({ShapeKindNames[Kind(_fuzzShapes[i])]}), centre {V(position)}";
                    Fail("tunnel", message);
                    if (PenetrationLogs.Count < 20)
                    {
                        PenetrationLogs.Add(message);
                    }

                    if (depth > DeepestPenetration)
                    {
                        DeepestPenetration = depth;
                        DeepestPenetrationCall = message;
                    }
                }
                else if (endOfStep && depth > ShallowTolerance + rounding)
                {
                    ShallowPenetrations++;
                    _clear[i] = false;
                    Fail("shallow", $"{_log}// at t = {time:R} (step end) the ball is {depth:R} m into shapes[{i}] ({ShapeKindNames[Kind(_fuzzShapes[i])]}), centre {V(position)}");
                }
            }
        }

        private static int Kind(ContactShape s) => s switch
        {
            NetMeshShape _ => 6,
            BoxShape b => Math.Min(b.HalfExtentsM.X, Math.Min(b.HalfExtentsM.Y, b.HalfExtentsM.Z)) < 1e-3 ? 1 : 0,
            CapsuleShape _ => 2,
            CylinderShape _ => 3,
            SphereShape _ => 4,
            _ => 5,
        };

        // ---- Generators ----

        // A model: mostly a preset in sea-level air or vacuum, under ZUp, YUp, tilted or no gravity; else a random ball with
        // Stepanek's laws; now and then one of the hostile models of the rest of the fuzz. The code that builds it, for a repro.
        private (FlightModel?, string) ShapeModel()
        {
            if (_random.Next(20) == 0)
            {
                FlightModel? hostile = Model();
                return (hostile, $"/* hostile */ {hostile}");
            }

            (Vector3d gravity, string gravityCode) = _random.Next(10) switch
            {
                0 => (MagnusBall.Gravity.YUp, "Gravity.YUp"),
                1 => (Vector3d.Zero, "Vector3d.Zero"),
                2 => (new Vector3d(0.5, -0.3, -9.8), "new Vector3d(0.5, -0.3, -9.8)"),
                _ => (MagnusBall.Gravity.ZUp, "Gravity.ZUp"),
            };
            bool air = _random.Next(4) != 0;
            string airCode = air ? "Air.SeaLevel" : "new Air(0, Vector3d.Zero)";
            Air theAir = air ? Air.SeaLevel : new Air(0, Vector3d.Zero);
            if (_random.Next(3) != 0)
            {
                SportPreset preset = SportPresets.All[_random.Next(SportPresets.All.Count)];
                return (preset.CreateModel(theAir, gravity), $"SportPresets.FromName(\"{preset.Name}\").CreateModel({airCode}, {gravityCode})");
            }

            double radius = Math.Pow(10, -2.5 + 2.5 * _random.NextDouble()); // 3 mm to 1 m
            double mass = Math.Pow(10, -3.5 + 4 * _random.NextDouble());     // 0.3 g to 3 kg
            double inertia = 0.05 + 0.95 * _random.NextDouble();
            var model = new FlightModel(new Ball(mass, radius, inertia), theAir, gravity, StepanekDrag.Instance, StepanekLift.Instance, null);
            return (model, $"new FlightModel(new Ball({mass:R}, {radius:R}, {inertia:R}), {airCode}, {gravityCode}, StepanekDrag.Instance, StepanekLift.Instance, null)");
        }

        // 1-8 shapes near the origin's 20 m, or a fixture; null when a hostile constructor refused (judged and counted as a call).
        private ContactShape[]? Shapes(FlightModel model, Vector3d up, out string code)
        {
            ShapeSets++;
            var list = new List<ContactShape>();
            var codes = new List<string>();
            if (_random.Next(5) == 0)
            {
                Vector3d foot = new Vector3d(20 * _random.NextDouble() - 5, 10 * _random.NextDouble() - 5, 0);
                Vector3d across = _random.Next(2) == 0 ? Vector3d.UnitY : Unit();
                int fixture = _random.Next(4);
                string name = fixture switch { 0 => "TennisNet", 1 => "SoccerGoalFrame", 2 => "BasketballHoop", _ => "TableTennisNet" };
                ContactShape[]? made = Construct(() => fixture switch
                {
                    0 => SportShapes.TennisNet(list.Count, foot, across, up),
                    1 => SportShapes.SoccerGoalFrame(list.Count, foot, across, up),
                    2 => SportShapes.BasketballHoop(list.Count, foot, across, up),
                    _ => SportShapes.TableTennisNet(list.Count, foot, across, up),
                }, "SportShapes." + name);
                if (made != null)
                {
                    list.AddRange(made);
                    codes.Add($"..SportShapes.{name}(0, {V(foot)}, {V(across)}, {V(up)})");
                }
            }

            int count = 1 + _random.Next(8);
            for (int i = 0; i < count; i++)
            {
                string shapeCode = string.Empty;
                ContactShape? shape = Construct(() => OneShape(list.Count, model, out shapeCode), "a shape");
                if (shape == null)
                {
                    code = string.Empty;
                    return null;
                }

                list.Add(shape);
                codes.Add(shapeCode);
            }

            code = "[" + string.Join(", ", codes) + "]"; // a collection expression (C# 12): the fixtures spread in
            return list.ToArray();
        }

        private ContactShape OneShape(int id, FlightModel model, out string code)
        {
            bool hostile = _random.Next(40) == 0;
            Vector3d centre = new Vector3d(20 * _random.NextDouble() - 5, 10 * _random.NextDouble() - 5, 4 * _random.NextDouble() - 0.5);
            double size = Size();
            ContactProperties contact = Properties(out string contactCode);
            double mass = double.PositiveInfinity;
            if (_random.Next(3) == 0)
            {
                // Down to just over the stepper's floor (1e-12 of the ball's mass), and now and then below it (refused by the stepper).
                mass = model.Ball.Mass * Math.Pow(10, (_random.Next(20) == 0 ? -13 : -11.9) + 15 * _random.NextDouble());
            }

            string massCode = double.IsPositiveInfinity(mass) ? "double.PositiveInfinity" : mass.ToString("R", CultureInfo.InvariantCulture);
            if (hostile)
            {
                // An invalid argument: each constructor must refuse it with an ArgumentException naming it.
                size = _random.Next(4) switch { 0 => 0, 1 => -size, 2 => double.NaN, _ => double.PositiveInfinity };
            }

            switch (_random.Next(8))
            {
                case 0:
                case 1:
                {
                    var half = new Vector3d(Size(), Size(), Size());
                    if (hostile)
                    {
                        half = new Vector3d(size, 1, 1);
                    }

                    Vector3d x = Unit(), y = Unit();
                    code = $"new BoxShape({id}, {V(centre)}, {V(half)}, {V(x)}, {V(y)}, {contactCode}, {massCode})";
                    return new BoxShape(id, centre, half, x, y, contact, mass);
                }

                case 2:
                {
                    Vector3d x = Unit(), y = Unit();
                    if (_random.Next(2) == 0)
                    {
                        double w = Size(), h = hostile ? size : Size();
                        code = $"BoxShape.Rectangle({id}, {V(centre)}, {V(y)}, {V(x)}, {w:R}, {h:R}, {contactCode}, {massCode})";
                        return BoxShape.Rectangle(id, centre, y, x, w, h, contact, mass);
                    }

                    // A thin box: 1 micrometre to 1 mm thick.
                    var half = new Vector3d(Size(), Size(), Math.Pow(10, -6 + 3 * _random.NextDouble()));
                    code = $"new BoxShape({id}, {V(centre)}, {V(half)}, {V(x)}, {V(y)}, {contactCode}, {massCode})";
                    return new BoxShape(id, centre, half, x, y, contact, mass);
                }

                case 3:
                {
                    Vector3d b = centre + Unit() * Size();
                    code = $"new CapsuleShape({id}, {V(centre)}, {V(b)}, {size:R}, {contactCode}, {massCode})";
                    return new CapsuleShape(id, centre, b, size, contact, mass);
                }

                case 4:
                {
                    Vector3d b = centre + Unit() * Size();
                    code = $"new CylinderShape({id}, {V(centre)}, {V(b)}, {size:R}, {contactCode}, {massCode})";
                    return new CylinderShape(id, centre, b, size, contact, mass);
                }

                case 5:
                    code = $"new SphereShape({id}, {V(centre)}, {size:R}, {contactCode}, {massCode})";
                    return new SphereShape(id, centre, size, contact, mass);
                case 6:
                {
                    Vector3d axis = _random.Next(2) == 0 ? model.Up.LengthSquared > 0 ? model.Up : Vector3d.UnitZ : Unit();
                    double ring = Size(), tube = hostile ? size : Size() * (_random.Next(2) == 0 ? 0.05 : 1);
                    code = $"new TorusShape({id}, {V(centre)}, {V(axis)}, {ring:R}, {tube:R}, {contactCode}, {massCode})";
                    return new TorusShape(id, centre, axis, ring, tube, contact, mass);
                }

                default:
                {
                    Vector3d n = Unit(), w = Unit();
                    double width = Size(), height = hostile ? size : Size(), kept = _random.NextDouble();
                    code = $"new NetMeshShape({id}, {V(centre)}, {V(n)}, {V(w)}, {width:R}, {height:R}, {kept:R}, {massCode})";
                    return new NetMeshShape(id, centre, n, w, width, height, kept, mass);
                }
            }
        }

        // A size: log-uniform from 1 mm to 30 m.
        private double Size() => Math.Pow(10, -3 + 4.477 * _random.NextDouble());

        private ContactProperties Properties(out string code)
        {
            double e = _random.Next(8) == 0 ? (_random.Next(2) == 0 ? 0 : 1) : _random.NextDouble();
            double mu = _random.Next(8) == 0 ? (_random.Next(2) == 0 ? 0 : 10 * _random.NextDouble()) : _random.NextDouble();
            double ex = _random.Next(3) == 0 ? _random.NextDouble() : 0;
            double d0 = _random.Next(4) == 0 ? 0.01 * _random.NextDouble() : 0;
            double k = _random.Next(4) == 0 ? 0.02 * _random.NextDouble() - 0.01 : 0;
            double d1 = _random.Next(4) == 0 ? 1e-3 * _random.NextDouble() : 0;
            code = $"new ContactProperties({e:R}, {mu:R}, {ex:R}, {d0:R}, {k:R}, {d1:R})";
            return new ContactProperties(e, mu, ex, d0, k, d1);
        }

        // A valid state, mostly about a shape: aimed at it from a few metres, touching it, just inside it, or laid slowly on its top.
        private FlightState ShapeState(FlightModel model, Vector3d up, ContactShape[] shapes)
        {
            if (_random.Next(40) == 0)
            {
                return new FlightState(new Vector3d(double.NaN, 0, 0), Vector3d.Zero, Vector3d.Zero, 0);
            }

            double r = model.Ball.Radius;
            Vector3d spin = Unit() * (_random.Next(4) == 0 ? 0 : Math.Pow(10, -1 + 4 * _random.NextDouble())); // up to 1000 rad/s
            double time = _random.Next(4) == 0 ? 1e3 * _random.NextDouble() : 0;
            ContactShape shape = shapes[_random.Next(shapes.Length)];
            Vector3d target = (shape.BoundsMin + shape.BoundsMax) * 0.5;
            switch (_random.Next(5))
            {
                case 0:
                {
                    // Random, anywhere near.
                    var p = new Vector3d(20 * _random.NextDouble() - 5, 10 * _random.NextDouble() - 5, 5 * _random.NextDouble());
                    return new FlightState(p, Unit() * Speed(), spin, time);
                }

                case 1:
                {
                    // From a few metres, at the shape's centre (or near it), fast or slow.
                    Vector3d from = target + Unit() * (r + Math.Pow(10, -2 + 3 * _random.NextDouble()) + (shape.BoundsMax - shape.BoundsMin).Length * 0.5);
                    Vector3d aim = target + Unit() * 0.3 * _random.NextDouble() - from;
                    return new FlightState(from, aim.NormalizedOrZero() * Speed(), spin, time);
                }

                default:
                {
                    // Touching, just outside or just inside: a point of the surface (the nearest to a random point), its normal.
                    Vector3d probe = target + Unit() * (shape.BoundsMax - shape.BoundsMin).Length;
                    if (_random.Next(3) == 0)
                    {
                        probe = target + up * (shape.BoundsMax - shape.BoundsMin).Length; // above it: its top
                    }

                    double d = shape.SignedDistance(probe, out Vector3d n);
                    Vector3d surface = probe - n * d;
                    shape.SignedDistance(surface, out n);
                    double offset = _random.Next(4) switch
                    {
                        0 => 0,
                        1 => Math.Pow(10, -10 + 8 * _random.NextDouble()),   // just outside
                        2 => -Math.Pow(10, -10 + 7 * _random.NextDouble()),  // just inside
                        _ => 0.05 * _random.NextDouble(),
                    };
                    Vector3d v = _random.Next(2) == 0
                        ? Unit() * 0.3 * _random.NextDouble()                      // slow: settles or rolls
                        : (Unit() - n * _random.NextDouble()).NormalizedOrZero() * Speed();
                    return new FlightState(surface + n * (r + offset), v, spin, time);
                }
            }
        }

        // A speed: log-uniform from 1 mm/s to 150 m/s, now and then zero.
        private double Speed() => _random.Next(10) == 0 ? 0 : Math.Pow(10, -3 + 5.176 * _random.NextDouble());

        // A step: log-uniform 1e-5 s to 5 s, now and then zero, negative or not finite.
        private double ShapeStep()
        {
            if (_random.Next(40) == 0)
            {
                return _random.Next(4) switch { 0 => 0, 1 => -1.0 / 60, 2 => double.NaN, _ => double.PositiveInfinity };
            }

            return Math.Pow(10, -5 + 5.7 * _random.NextDouble());
        }

        private Vector3d Unit()
        {
            while (true)
            {
                var v = new Vector3d(2 * _random.NextDouble() - 1, 2 * _random.NextDouble() - 1, 2 * _random.NextDouble() - 1);
                double l = v.Length;
                if (l > 0.1 && l <= 1)
                {
                    return v / l;
                }
            }
        }

        private static string BounceName(IBounceModel b) =>
            ReferenceEquals(b, CrossBounce.Hard) ? "Hard" : ReferenceEquals(b, CrossBounce.Clay) ? "Clay" : "Grass";

        private static string V(in Vector3d v) => string.Format(CultureInfo.InvariantCulture, "new Vector3d({0:R}, {1:R}, {2:R})", v.X, v.Y, v.Z);

        private static string S(in FlightState s) => $"new FlightState({V(s.Position)}, {V(s.Velocity)}, {V(s.AngularVelocity)}, {s.Time.ToString("R", CultureInfo.InvariantCulture)})";
    }
}
