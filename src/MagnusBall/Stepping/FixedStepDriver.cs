using System;
using MagnusBall.Integration;

namespace MagnusBall.Stepping
{
    /// <summary>
    /// Turns a game engine's variable frame time into fixed integration steps, so that a shot flies the same
    /// path at 30, 60 or 144 frames per second and through hitches: the MonoBehaviour-style adapter. Call
    /// <see cref="Advance(double, Span{FrameEvent})"/> once per frame with the frame's delta time, then draw
    /// the ball at <see cref="RenderState"/>.
    /// </summary>
    /// <remarks>
    /// <para>The pattern is Fiedler's "Fix Your Timestep!" (Gaffer On Games, 2004): frame time goes into an
    /// accumulator; whole fixed steps are taken out of it; what is left (less than one step) says how far
    /// the renderer is between the last two fixed states, alpha = accumulator / step. A frame longer than
    /// <see cref="MaxFrameDeltaSeconds"/> (a hitch: loading, a breakpoint, the window dragged) is clamped, and
    /// at most <see cref="MaxStepsPerAdvance"/> steps are taken per call, so one slow frame cannot trigger
    /// ever more steps (the "spiral of death"). Time that is clamped or capped away is dropped: the ball
    /// falls behind the wall clock but flies exactly the same path, because the path depends only on the
    /// sequence of fixed steps, never on how frame time was sliced.</para>
    /// <para>The seed thesis (Agrawal 2023, section 3.1.3) stepped its ODE once per frame with Unity's
    /// <c>Time.deltaTime</c>, so its landing point depended on the frame rate; docs/unity.md puts numbers
    /// on that difference.</para>
    /// <para>Events (the landing, plane crossings) are located inside the step where they happen on the
    /// cubic Hermite interpolant of the step's two end states and derivatives (no extra derivative
    /// evaluation), and reported in a caller-provided buffer. Nothing here allocates after construction.</para>
    /// <para>Without a bounce model the flight ends at the landing: the state stays at the landing state
    /// and <see cref="HasLanded"/> turns true. A driver owns its state and is not thread-safe; the model and
    /// integrator it steps are immutable and may be shared by any number of drivers on any threads.</para>
    /// </remarks>
    public sealed class FixedStepDriver
    {
        /// <summary>The default frame-time clamp, 0.25 s (Fiedler 2004).</summary>
        public const double DefaultMaxFrameDeltaSeconds = 0.25;

        private readonly Vector3d _groundPoint;
        private readonly Vector3d _groundNormal;
        private readonly bool _hasGround;
        private readonly FlightPlane[] _planes;

        private FlightState _state;
        private StateDerivative _derivative;
        private FlightState _previous;
        private StateDerivative _previousDerivative;
        private double _accumulator;
        private bool _landed;
        private long _totalSteps;

        /// <summary>
        /// Creates a driver for one ball.
        /// </summary>
        /// <param name="model">The flight model (shared, immutable).</param>
        /// <param name="integrator">The integrator (shared, stateless).</param>
        /// <param name="fixedStep">The fixed step, s; finite and &gt; 0 (for example 1/240).</param>
        /// <param name="start">The launch state; every component finite.</param>
        /// <param name="groundPoint">
        /// A point of the ground plane, m; its normal is the model's up (-gravity). Put it one ball radius above
        /// the court to land when the ball touches the court rather than when its centre reaches it.
        /// </param>
        /// <param name="planes">Planes whose crossings are reported (copied once here); null for none.</param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s; finite and &gt; 0. Default 0.25 s.</param>
        /// <param name="maxStepsPerAdvance">
        /// The most fixed steps one <see cref="Advance(double, Span{FrameEvent})"/> call takes; &gt;= 1, or 0
        /// (the default) for ceil(maxFrameDeltaSeconds / fixedStep) + 1, so that the clamp binds first.
        /// </param>
        /// <exception cref="ArgumentNullException">model or integrator is null.</exception>
        /// <exception cref="ArgumentException">A number is out of its range; the message names it.</exception>
        public FixedStepDriver(
            FlightModel model,
            IIntegrator integrator,
            double fixedStep,
            in FlightState start,
            Vector3d groundPoint = default,
            FlightPlane[]? planes = null,
            double maxFrameDeltaSeconds = DefaultMaxFrameDeltaSeconds,
            int maxStepsPerAdvance = 0)
        {
            Model = Require.NotNull(model, nameof(model));
            Integrator = Require.NotNull(integrator, nameof(integrator));
            FixedStep = Require.Step(fixedStep, nameof(fixedStep));
            RequireFiniteState(start, nameof(start));
            _groundPoint = Require.Finite(groundPoint, nameof(groundPoint));
            MaxFrameDeltaSeconds = Require.Positive(maxFrameDeltaSeconds, nameof(maxFrameDeltaSeconds));
            if (maxStepsPerAdvance < 0)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(maxStepsPerAdvance), maxStepsPerAdvance, $"maxStepsPerAdvance must be >= 1, or 0 for the default; got {maxStepsPerAdvance}.");
            }

            double defaultSteps = Math.Ceiling(maxFrameDeltaSeconds / fixedStep) + 1;
            MaxStepsPerAdvance = maxStepsPerAdvance > 0 ? maxStepsPerAdvance : (int)Math.Min(defaultSteps, int.MaxValue);

            _groundNormal = model.Up;
            _hasGround = model.Up.LengthSquared > 0;
            _planes = planes == null ? Array.Empty<FlightPlane>() : (FlightPlane[])planes.Clone();
            Reset(start);
        }

        /// <summary>The flight model being stepped.</summary>
        public FlightModel Model { get; }

        /// <summary>The integrator.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The fixed step, s.</summary>
        public double FixedStep { get; }

        /// <summary>The frame-time clamp, s.</summary>
        public double MaxFrameDeltaSeconds { get; }

        /// <summary>The most fixed steps one Advance call takes.</summary>
        public int MaxStepsPerAdvance { get; }

        /// <summary>The planes whose crossings are reported (a copy; changing it changes nothing).</summary>
        public FlightPlane[] Planes => (FlightPlane[])_planes.Clone();

        /// <summary>The latest fixed state (the simulation's "now"); the landing state once landed.</summary>
        public FlightState State => _state;

        /// <summary>The fixed state before <see cref="State"/> (equal to it right after a reset).</summary>
        public FlightState PreviousState => _previous;

        /// <summary>Frame time not yet simulated, s: in [0, <see cref="FixedStep"/>).</summary>
        public double Accumulator => _accumulator;

        /// <summary>How far the render state is from <see cref="PreviousState"/> toward <see cref="State"/>, accumulator / step, in [0, 1].</summary>
        public double Alpha => Math.Min(1.0, _accumulator / FixedStep);

        /// <summary>True once the ball has crossed the ground: the flight has ended and Advance takes no more steps.</summary>
        public bool HasLanded => _landed;

        /// <summary>Fixed steps taken since the last reset.</summary>
        public long TotalSteps => _totalSteps;

        /// <summary>
        /// The simulation time the renderer should show, s: <see cref="PreviousState"/>'s time plus the
        /// accumulator, never past <see cref="State"/>'s time.
        /// </summary>
        public double RenderTime => RenderFraction() * (_state.Time - _previous.Time) + _previous.Time;

        /// <summary>
        /// The state to draw this frame: the cubic Hermite interpolant between <see cref="PreviousState"/>
        /// and <see cref="State"/> (both ends' derivatives, so the drawn path is C1 and keeps the
        /// curvature a linear blend would cut), evaluated at alpha = accumulator / step.
        /// </summary>
        public FlightState RenderState => CubicHermite.Interpolate(_previous, _previousDerivative, _state, _derivative, RenderFraction());

        /// <summary>
        /// Restarts the flight from <paramref name="start"/>: clears the accumulator and the landed flag.
        /// </summary>
        /// <param name="start">The launch state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite (nothing is changed).</exception>
        public void Reset(in FlightState start)
        {
            RequireFiniteState(start, nameof(start));
            _state = start;
            _derivative = Model.Derivative(start);
            _previous = start;
            _previousDerivative = _derivative;
            _accumulator = 0;
            _landed = false;
            _totalSteps = 0;
        }

        /// <summary>
        /// Consumes one frame's time without reporting events (the landing still ends the flight; read
        /// <see cref="HasLanded"/>).
        /// </summary>
        /// <param name="frameDeltaSeconds">The frame's delta time, s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">The delta is negative, NaN or infinite (nothing is changed).</exception>
        public AdvanceResult Advance(double frameDeltaSeconds) => Advance(frameDeltaSeconds, Span<FrameEvent>.Empty);

        /// <summary>
        /// Consumes one frame's time in fixed steps and writes what happened in them into
        /// <paramref name="events"/>, in time order. Allocates nothing.
        /// </summary>
        /// <param name="frameDeltaSeconds">
        /// The frame's delta time, s (Unity: <c>Time.deltaTime</c>); finite and &gt;= 0. Values above
        /// <see cref="MaxFrameDeltaSeconds"/> are clamped to it.
        /// </param>
        /// <param name="events">Where to write the events; those that do not fit are counted in the result.</param>
        /// <returns>Steps taken, events written and lost, and frame time dropped.</returns>
        /// <exception cref="ArgumentOutOfRangeException">The delta is negative, NaN or infinite (nothing is changed).</exception>
        public AdvanceResult Advance(double frameDeltaSeconds, Span<FrameEvent> events)
        {
            if (!double.IsFinite(frameDeltaSeconds) || frameDeltaSeconds < 0)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(frameDeltaSeconds), frameDeltaSeconds,
                    $"frameDeltaSeconds must be a finite frame time >= 0 s; got {Require.Format(frameDeltaSeconds)}.");
            }

            double dropped = 0;
            if (frameDeltaSeconds > MaxFrameDeltaSeconds)
            {
                dropped = frameDeltaSeconds - MaxFrameDeltaSeconds;
                frameDeltaSeconds = MaxFrameDeltaSeconds;
            }

            if (_landed)
            {
                // The flight is over: let the render state run to the landing and stay there.
                _accumulator = Math.Min(_accumulator + frameDeltaSeconds, FixedStep);
                return new AdvanceResult(0, 0, 0, dropped + frameDeltaSeconds);
            }

            _accumulator += frameDeltaSeconds;
            int steps = 0;
            int written = 0;
            int lost = 0;
            while (_accumulator >= FixedStep)
            {
                if (steps == MaxStepsPerAdvance)
                {
                    // Substep cap reached: keep the fraction of a step (alpha stays continuous), drop the rest.
                    double keep = _accumulator % FixedStep;
                    dropped += _accumulator - keep;
                    _accumulator = keep;
                    break;
                }

                FlightState next = Integrator.Step(Model, _state, _derivative, FixedStep);
                StateDerivative nextDerivative = Model.Derivative(next);
                steps++;
                _totalSteps++;
                _accumulator -= FixedStep;

                bool landed = LocateEvents(next, nextDerivative, events, ref written, ref lost, out FlightState landing);
                _previous = _state;
                _previousDerivative = _derivative;
                if (landed)
                {
                    _state = landing;
                    _derivative = Model.Derivative(landing);
                    _landed = true;
                    break;
                }

                _state = next;
                _derivative = nextDerivative;
            }

            return new AdvanceResult(steps, written, lost, dropped);
        }

        /// <summary>
        /// Finds the events in the step from the current state to <paramref name="next"/>, writes them in
        /// time order, and says whether the ball landed in it (plane crossings after the landing are not
        /// reported: the flight ends there).
        /// </summary>
        private bool LocateEvents(
            in FlightState next, in StateDerivative nextDerivative, Span<FrameEvent> events, ref int written, ref int lost, out FlightState landing)
        {
            landing = default;
            double landingFraction = double.PositiveInfinity;
            if (_hasGround)
            {
                double h0 = Vector3d.Dot(_state.Position - _groundPoint, _groundNormal);
                double h1 = Vector3d.Dot(next.Position - _groundPoint, _groundNormal);
                if (h0 >= 0 && h1 < 0)
                {
                    landingFraction = CubicHermite.Crossing(_state, _derivative, next, nextDerivative, _groundPoint, _groundNormal);
                    landing = CubicHermite.Interpolate(_state, _derivative, next, nextDerivative, landingFraction);
                }
            }

            int firstOfStep = written;
            for (int i = 0; i < _planes.Length; i++)
            {
                FlightPlane plane = _planes[i];
                double d0 = Vector3d.Dot(_state.Position - plane.Point, plane.Normal);
                double d1 = Vector3d.Dot(next.Position - plane.Point, plane.Normal);
                if (d0 < 0 && d1 >= 0)
                {
                    double fraction = CubicHermite.Crossing(_state, _derivative, next, nextDerivative, plane.Point, plane.Normal, upward: true);
                    if (fraction <= landingFraction)
                    {
                        var crossing = new FrameEvent(
                            FrameEventKind.PlaneCrossing, i, CubicHermite.Interpolate(_state, _derivative, next, nextDerivative, fraction));
                        Write(crossing, events, firstOfStep, ref written, ref lost);
                    }
                }
            }

            if (landingFraction <= 1)
            {
                Write(new FrameEvent(FrameEventKind.Landing, -1, landing), events, firstOfStep, ref written, ref lost);
                return true;
            }

            return false;
        }

        /// <summary>Inserts an event among this step's events, keeping them sorted by time (insertion sort, no allocation).</summary>
        private static void Write(in FrameEvent item, Span<FrameEvent> events, int firstOfStep, ref int written, ref int lost)
        {
            if (written >= events.Length)
            {
                lost++;
                return;
            }

            int i = written;
            while (i > firstOfStep && events[i - 1].Time > item.Time)
            {
                events[i] = events[i - 1];
                i--;
            }

            events[i] = item;
            written++;
        }

        private double RenderFraction()
        {
            double span = _state.Time - _previous.Time;
            if (!(span > 0))
            {
                return 0;
            }

            return Math.Min(_accumulator, span) / span;
        }

        private static void RequireFiniteState(in FlightState state, string name)
        {
            if (!state.IsFinite)
            {
                throw new ArgumentException($"{name} must have finite position, velocity, angular velocity and time; got {state}.", name);
            }
        }
    }
}
