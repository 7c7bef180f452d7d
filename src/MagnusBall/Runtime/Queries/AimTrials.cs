using System;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;

namespace MagnusBall.Queries
{
    /// <summary>
    /// What one aim solve launches at: the launch point, its frame and spin, the plane a trial must cross, the point whose
    /// height it must reach there, and whether <see cref="AimSolution.Miss"/> is the distance to that point (target solves)
    /// or the clearance (clearing a plane).
    /// </summary>
    internal readonly struct AimGoal
    {
        public readonly Vector3d Position;
        public readonly LaunchFrame Frame;
        public readonly LaunchSpin Spin;
        public readonly Plane Plane;
        public readonly Vector3d Target;
        public readonly bool MissToTarget;

        /// <summary>True for a bank shot: the trial arrives only at a crossing after it touched the shapes of id <see cref="ViaId"/>.</summary>
        public readonly bool HasVia;

        /// <summary>The id of the shapes a bank shot must touch first (see <see cref="HasVia"/>).</summary>
        public readonly int ViaId;

        public AimGoal(in Vector3d position, in LaunchFrame frame, in LaunchSpin spin, in Plane plane, in Vector3d target, bool missToTarget,
            bool hasVia = false, int viaId = 0)
        {
            Position = position;
            Frame = frame;
            Spin = spin;
            Plane = plane;
            Target = target;
            MissToTarget = missToTarget;
            HasVia = hasVia;
            ViaId = viaId;
        }

        /// <summary>The target's height above the launch point, along up, m (infinite where it exceeds a double, never NaN).</summary>
        public double Rise => Vector3d.DotOfDifference(Target, Position, Frame.Up);
    }

    /// <summary>
    /// The aim solver's trial flights, through the one flight core (<see cref="FlightStepper"/>): either adaptive
    /// Dormand-Prince 5(4) steps with the events located on its own interpolant (<see cref="FlightStepper.TryStepAdaptive"/>),
    /// or fixed steps of a given integrator with the events on each step's cubic Hermite. A trial "arrives" when it crosses
    /// the goal's plane along its normal before it lands on the ground. Counts the flights of the current solve. Holds one
    /// stepper: not thread-safe.
    /// </summary>
    internal sealed class AimTrials
    {
        /// <summary>The most adaptive steps one trial takes; a trial that needs more fails (its margin is -infinity).</summary>
        public const int MaximumAdaptiveSteps = 100_000;

        private readonly FlightStepper _stepper;
        // With the solver's shapes: the check flight of a solution (every shape), and the trials of a bank shot (the shapes of
        // its via id alone; built on the first solve with that id, kept for the next). Null without shapes.
        private readonly FlightStepper? _world;
        private readonly ContactShape[]? _shapes;
        private readonly FlightModel _model;
        private readonly IIntegrator _integrator;
        private readonly Plane _ground;
        private FlightStepper? _via;
        private int _viaId;
        private readonly Plane[] _plane = new Plane[1]; // the current trial's plane, watched by _stepper's event set
        private readonly DormandPrince54? _adaptive;
        private readonly DormandPrince54? _coarse;
        private readonly double _step;
        private readonly double _maximumFlightTime;
        private readonly Vector3d _up;
        // The solve's first adaptive trial starts from DormandPrince54.InitialStep's rough estimate, which the controller then
        // grows at most fivefold a step; every later trial starts with the step the first trial's controller asked for at
        // its launch (DormandPrince54.StepAskedFor), scaled to the trial's tolerance by (tolerance / first's)^(1/5), the
        // controller's own law. Fixed for the rest of the solve, so every later trial's margin depends on its launch alone.
        // 0: no trial yet; -1: the first trial gave none (later trials start from InitialStep too).
        private double _firstStep;
        private double _firstTolerance;

        /// <param name="model">The flight model.</param>
        /// <param name="integrator">The fixed-step integrator, or for adaptive trials the Dormand-Prince method.</param>
        /// <param name="step">The fixed step, or the longest adaptive step, s.</param>
        /// <param name="ground">The ground plane.</param>
        /// <param name="maximumFlightTime">The longest trial, s.</param>
        /// <param name="adaptive">True: adaptive trials with <paramref name="integrator"/> (a <see cref="DormandPrince54"/>).</param>
        /// <param name="coarse">For adaptive trials, the looser method of <see cref="Coarse"/> trials (null: none).</param>
        /// <param name="shapes">The solver's shapes (checked, copied; null or empty: none).</param>
        public AimTrials(FlightModel model, IIntegrator integrator, double step, in Plane ground, double maximumFlightTime, bool adaptive, DormandPrince54? coarse,
            ContactShape[]? shapes = null)
        {
            _coarse = adaptive ? coarse : null;
            _stepper = new FlightStepper(model, integrator, FlightEventSet.Sharing(ground, _plane));
            _model = model;
            _integrator = integrator;
            _ground = ground;
            if (shapes != null && shapes.Length > 0)
            {
                _world = new FlightStepper(model, integrator, FlightEventSet.Sharing(ground, _plane), null, shapes);
                _shapes = (ContactShape[])shapes.Clone();
            }

            _adaptive = adaptive ? (DormandPrince54)integrator : null;
            _step = step;
            _maximumFlightTime = maximumFlightTime;
            _up = model.Up;
        }

        /// <summary>
        /// While true, adaptive trials fly with the coarse method (the early trials of a solve, far from its answer, where
        /// the solve needs the margin's sign and rough size only); fixed-step trials ignore it.
        /// </summary>
        public bool Coarse { get; set; }

        /// <summary>True when trials have a coarse method.</summary>
        public bool HasCoarse => _coarse != null;

        /// <summary>True when the trials are adaptive.</summary>
        public bool IsAdaptive => _adaptive != null;

        /// <summary>Flights since <see cref="StartSolve"/>.</summary>
        public int Flights { get; private set; }

        /// <summary>Model evaluations plus steps of the solve's finished trials.</summary>
        public long Work { get; private set; }

        /// <summary>True once the solve reached its <see cref="Budget"/>: later trials are not flown.</summary>
        public bool WorkLimitReached { get; private set; }

        /// <summary>The current solve's work budget: model evaluations plus steps over all its trials.</summary>
        public long Budget { get; private set; } = AimSolver.MaxEvaluationsPerSolve;

        /// <summary>Starts counting a new solve's flights and work, within <paramref name="budget"/> evaluations plus steps.</summary>
        public void StartSolve(long budget)
        {
            Flights = 0;
            Work = 0;
            WorkLimitReached = false;
            Budget = budget;
            _firstStep = 0;
        }

        /// <summary>
        /// Starts a second search within the solve (the lob after a blocked drive): its first trial sets the first step of
        /// the trials after it anew, so the search flies the same trials as a solve of its own; flights and work go on counting.
        /// </summary>
        public void RestartFirstStep() => _firstStep = 0;

        /// <summary>
        /// One trial launch at the given speed, elevation and azimuth: its signed margin (&gt;= 0 when it arrives at or
        /// above the goal's height; &lt; 0 when below or short (see <see cref="ShortMargin"/>: continuous for ground targets);
        /// negative infinity when it neither lands nor arrives in time) and the solution it
        /// stands for (Solved when the margin is &gt;= 0).
        /// </summary>
        public double Margin(in AimGoal goal, double speed, double elevation, double azimuth, out AimSolution solution)
        {
            Vector3d direction = goal.Frame.Direction(elevation, azimuth);
            Vector3d velocity = direction * speed;
            Vector3d spin = goal.Spin.AngularVelocity(direction, goal.Frame);
            double margin;
            FlightState arrival;
            bool landed;
            if (!spin.IsFinite || !velocity.IsFinite)
            {
                // Rates near double.MaxValue resolve to an angular velocity beyond what a double holds at this direction, or
                // a speed near double.MaxValue times the direction overflows (the state would refuse either): the trial
                // cannot be flown, and fails like a diverged one; not counted as a flight.
                spin = Vector3d.Zero;
                velocity = Vector3d.Zero;
                arrival = new FlightState(goal.Position, velocity, spin);
                margin = double.NegativeInfinity;
            }
            else if (Fly(new FlightState(goal.Position, velocity, spin), goal, out arrival, out landed))
            {
                margin = Vector3d.DotOfDifference(arrival.Position, goal.Target, _up); // never NaN: the target may be near 1e308 away
            }
            else
            {
                // A bank shot's trial that lands before it touched its shape did not bank (margin -infinity, as a failed trial).
                margin = landed && (!goal.HasVia || _viaTouched) ? ShortMargin(goal, arrival) : double.NegativeInfinity;
            }

            double miss = goal.MissToTarget ? Vector3d.Distance(arrival.Position, goal.Target) : margin;
            solution = new AimSolution(
                margin >= 0 ? AimStatus.Solved : AimStatus.Unreachable, speed, elevation, azimuth, velocity, spin, arrival, miss, Flights);
            return margin;
        }

        /// <summary>
        /// The margin of a trial that lands short of the plane (&lt; 0): the height, relative to the goal's, at which the
        /// landing's straight line (its velocity) meets the plane. It meets the margin of the trials that arrive at the
        /// landing that just reaches the plane (for a target on the ground both are 0 there) with the same slope to first
        /// order, so the secant steps do not see a kink there. Where the landing does not move toward the plane, the
        /// landing's signed distance to it.
        /// </summary>
        private double ShortMargin(in AimGoal goal, in FlightState landing)
        {
            double distance = goal.Plane.SignedDistance(landing.Position); // < 0: short of the plane
            double toward = Vector3d.Dot(landing.Velocity, goal.Plane.Normal);
            double extended = double.NaN;
            if (toward > 0)
            {
                extended = Vector3d.DotOfDifference(landing.Position, goal.Target, _up) - Vector3d.Dot(landing.Velocity, _up) * (distance / toward);
            }

            return Math.Min(double.IsFinite(extended) ? extended : distance, -double.Epsilon);
        }

        /// <summary>
        /// Flies one trial to the goal's plane (after its via shape, for a bank shot): true with the crossing state when the ball crosses it along its
        /// normal before landing; false with the landing (or last) state otherwise.
        /// </summary>
        private bool Fly(in FlightState launch, in AimGoal goal, out FlightState arrival, out bool landed)
        {
            _viaTouched = false;
            if (WorkLimitReached)
            {
                // Past the work cap: no more trials are flown (each fails), so the solve ends quickly.
                arrival = launch;
                landed = false;
                return false;
            }

            FlightStepper stepper = goal.HasVia ? ViaStepper(goal.ViaId) : _stepper;
            bool arrived = FlyTrial(stepper, launch, goal, out arrival, out landed);
            Work += stepper.DerivativeEvaluations + stepper.StepCount;
            return arrived;
        }

        // A later trial's first step (see _firstStep): the first trial's, scaled to this method's tolerance. The power is
        // DormandPrince54's portable x^(-1/5), so the step is the same on every runtime.
        private double FirstStep(DormandPrince54 method)
        {
            double tolerance = method.RelativeTolerance;
            return tolerance == _firstTolerance ? _firstStep : _firstStep * DormandPrince54.PowMinusOneFifth(_firstTolerance / tolerance);
        }

        private bool FlyTrial(FlightStepper stepper, in FlightState launch, in AimGoal goal, out FlightState arrival, out bool landed)
        {
            Flights++;
            _plane[0] = goal.Plane;
            stepper.Reset(launch);
            double endTime = launch.Time + _maximumFlightTime;
            // A bank shot's trial does not stop at a crossing: only one after its touch of the shape counts (found below).
            FlightEventKinds stopAt = goal.HasVia ? FlightEventKinds.Landing : FlightEventKinds.Landing | FlightEventKinds.PlaneCrossing;
            // Bounded: fixed trials advance the clock by a step per pass (at most maximumFlightTime / step + 1 passes, the
            // last step trimmed to the time limit by the one end-time rule); adaptive trials take at most
            // MaximumAdaptiveSteps steps; no trial goes past the solve's work budget.
            for (int pass = 0; ; pass++)
            {
                if (Work + stepper.DerivativeEvaluations + stepper.StepCount >= Budget)
                {
                    WorkLimitReached = true; // this trial fails; the solve returns WorkLimitReached
                    break;
                }

                bool last;
                StepOutcome outcome;
                if (_adaptive != null)
                {
                    double left = endTime - stepper.CurrentTime;
                    if (!(left > 0) || pass >= MaximumAdaptiveSteps)
                    {
                        break;
                    }

                    last = false; // the check above ends the loop at the time limit
                    DormandPrince54 method = Coarse && _coarse != null ? _coarse : _adaptive;
                    if (pass == 0 && _firstStep > 0)
                    {
                        stepper.SetNextAdaptiveStep(FirstStep(method));
                    }

                    outcome = stepper.TryStepAdaptive(method, Math.Min(left, _step), stopAt);
                    if (pass == 0 && _firstStep == 0)
                    {
                        double asked = DormandPrince54.StepAskedFor(stepper.LastAdaptiveStep);
                        _firstStep = asked > 0 ? Math.Min(asked, _step) : -1;
                        _firstTolerance = method.RelativeTolerance;
                    }
                }
                else
                {
                    double h = FlightStepper.StepTowardUnchecked(stepper.CurrentTime, endTime, _step, out last);
                    outcome = stepper.TryStep(h, stopAt);
                }

                if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                {
                    break; // this trial fails (margin -infinity), the solve goes on
                }

                if (goal.HasVia && ViaArrival(stepper, goal.ViaId, out arrival))
                {
                    landed = false;
                    return true;
                }

                if (stepper.IsStopped && goal.HasVia)
                {
                    arrival = stepper.StopEvent.State;
                    landed = true;
                    return false;
                }

                if (stepper.IsStopped)
                {
                    // A crossing at the same instant as the landing still arrives.
                    foreach (FlightEvent e in SpanView.Of(stepper.Events)) // not ReadOnlySpan's enumerator: Mono 6.8 lacks it
                    {
                        if (e.Kind == FlightEventKinds.PlaneCrossing)
                        {
                            arrival = e.State;
                            landed = false;
                            return true;
                        }
                    }

                    arrival = stepper.StopEvent.State;
                    landed = true;
                    return false;
                }

                if (last)
                {
                    break;
                }
            }

            arrival = stepper.State;
            landed = false;
            return false;
        }
        // True once the current bank-shot trial touched its shape.
        private bool _viaTouched;

        /// <summary>True when the solver has shapes.</summary>
        public bool HasShapes => _shapes != null;

        /// <summary>True when one of the solver's shapes has id <paramref name="id"/>.</summary>
        public bool HasShape(int id)
        {
            if (_shapes != null)
            {
                foreach (ContactShape shape in _shapes)
                {
                    if (shape.Id == id)
                    {
                        return true;
                    }
                }
            }

            return false;
        }

        /// <summary>The middle of the bounding boxes of the solver's shapes of id <paramref name="id"/> (one of them must exist).</summary>
        public Vector3d ShapeCentre(int id)
        {
            Vector3d lo = default, hi = default;
            bool any = false;
            foreach (ContactShape shape in _shapes!)
            {
                if (shape.Id == id)
                {
                    Vector3d a = shape.BoundsMin, b = shape.BoundsMax;
                    lo = any ? new Vector3d(Math.Min(lo.X, a.X), Math.Min(lo.Y, a.Y), Math.Min(lo.Z, a.Z)) : a;
                    hi = any ? new Vector3d(Math.Max(hi.X, b.X), Math.Max(hi.Y, b.Y), Math.Max(hi.Z, b.Z)) : b;
                    any = true;
                }
            }

            return (lo + hi) * 0.5;
        }

        // The stepper of a bank shot's trials: the shapes of its id alone (the others are met by the solution's check flight).
        private FlightStepper ViaStepper(int id)
        {
            if (_via == null || _viaId != id)
            {
                int count = 0;
                foreach (ContactShape shape in _shapes!)
                {
                    count += shape.Id == id ? 1 : 0;
                }

                var via = new ContactShape[count];
                count = 0;
                foreach (ContactShape shape in _shapes)
                {
                    if (shape.Id == id)
                    {
                        via[count++] = shape;
                    }
                }

                _via = new FlightStepper(_model, _integrator, FlightEventSet.Sharing(_ground, _plane), null, via);
                _viaId = id;
            }

            return _via;
        }

        // The last step's crossing of the goal's plane after the trial touched the shapes of id `via` (in this step or before).
        private bool ViaArrival(FlightStepper stepper, int via, out FlightState arrival)
        {
            foreach (FlightEvent e in SpanView.Of(stepper.Events))
            {
                if (e.Kind == FlightEventKinds.Contact && e.ShapeId == via)
                {
                    _viaTouched = true;
                }
                else if (e.Kind == FlightEventKinds.PlaneCrossing && _viaTouched)
                {
                    arrival = e.State;
                    return true;
                }
            }

            arrival = default;
            return false;
        }

        /// <summary>
        /// The check flight of a solution among every shape, to its goal's plane (after the via shape for a bank shot): true when
        /// it touches no shape but the via one before it arrives (or lands); false with the id of the first other shape touched.
        /// </summary>
        public bool ClearsShapes(in AimGoal goal, in AimSolution s, out int touched)
        {
            touched = 0;
            FlightStepper stepper = _world!;
            Flights++;
            _plane[0] = goal.Plane;
            stepper.Reset(new FlightState(goal.Position, s.Velocity, s.AngularVelocity));
            double endTime = stepper.CurrentTime + _maximumFlightTime;
            bool viaTouched = false;
            bool clear = true;
            for (int pass = 0; pass < MaximumAdaptiveSteps && !stepper.IsStopped; pass++)
            {
                double left = endTime - stepper.CurrentTime;
                if (!(left > 0) || Work + stepper.DerivativeEvaluations + stepper.StepCount >= Budget)
                {
                    break;
                }

                StepOutcome outcome = _adaptive != null
                    ? stepper.TryStepAdaptive(_adaptive, Math.Min(left, _step), FlightEventKinds.Landing)
                    : stepper.TryStep(FlightStepper.StepTowardUnchecked(stepper.CurrentTime, endTime, _step, out _), FlightEventKinds.Landing);
                if (outcome == StepOutcome.Diverged || outcome == StepOutcome.TimeCannotAdvance)
                {
                    break;
                }

                bool done = false;
                foreach (FlightEvent e in SpanView.Of(stepper.Events))
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        if (goal.HasVia && e.ShapeId == goal.ViaId && !viaTouched)
                        {
                            viaTouched = true;
                            continue;
                        }

                        touched = e.ShapeId;
                        clear = false;
                        done = true;
                        break;
                    }

                    if (e.Kind == FlightEventKinds.PlaneCrossing && (!goal.HasVia || viaTouched))
                    {
                        done = true;
                        break;
                    }
                }

                if (done)
                {
                    break;
                }
            }

            Work += stepper.DerivativeEvaluations + stepper.StepCount;
            return clear;
        }
    }
}
