using System;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Contact
{
    /// <summary>What a <see cref="BouncingFlight"/> ball is doing.</summary>
    public enum FlightPhase
    {
        /// <summary>In the air (between bounces): the flight model is integrated.</summary>
        Flying = 0,

        /// <summary>Rolling on the surface without slip, slowed by rolling resistance.</summary>
        Rolling = 1,

        /// <summary>At rest on the surface: nothing moves any more.</summary>
        Stopped = 2,
    }

    /// <summary>One bounce of a <see cref="BouncingFlight"/>: where and when, what came in and what went out.</summary>
    public readonly struct BounceEvent
    {
        /// <summary>The bounce's number in the flight, from 1.</summary>
        public readonly int Index;

        /// <summary>Contact time, s (located on the step's cubic Hermite interpolant).</summary>
        public readonly double Time;

        /// <summary>The ball's centre at contact, m (one radius above the surface).</summary>
        public readonly Vector3d Position;

        /// <summary>The point of the surface the ball touches, m (the centre minus one radius along the normal).</summary>
        public readonly Vector3d ContactPoint;

        /// <summary>Velocity just before the bounce, m/s.</summary>
        public readonly Vector3d IncomingVelocity;

        /// <summary>Angular velocity just before the bounce, rad/s.</summary>
        public readonly Vector3d IncomingAngularVelocity;

        /// <summary>The bounce: outgoing velocity and spin, regime, e_y.</summary>
        public readonly BounceOutcome Outcome;

        /// <summary>True when this bounce was too weak to leave the surface and the ball started rolling.</summary>
        public readonly bool StartedRolling;

        /// <summary>Creates an event.</summary>
        /// <param name="index">Bounce number, from 1.</param>
        /// <param name="time">Contact time, s.</param>
        /// <param name="position">Centre at contact, m.</param>
        /// <param name="contactPoint">Touched point of the surface, m.</param>
        /// <param name="incomingVelocity">Velocity before, m/s.</param>
        /// <param name="incomingAngularVelocity">Angular velocity before, rad/s.</param>
        /// <param name="outcome">The bounce.</param>
        /// <param name="startedRolling">Whether the ball started rolling.</param>
        public BounceEvent(
            int index, double time, in Vector3d position, in Vector3d contactPoint, in Vector3d incomingVelocity,
            in Vector3d incomingAngularVelocity, in BounceOutcome outcome, bool startedRolling)
        {
            Index = index;
            Time = time;
            Position = position;
            ContactPoint = contactPoint;
            IncomingVelocity = incomingVelocity;
            IncomingAngularVelocity = incomingAngularVelocity;
            Outcome = outcome;
            StartedRolling = startedRolling;
        }

        /// <inheritdoc />
        public override string ToString() => $"bounce {Index} at t={Time:R} s, contact {ContactPoint}: {Outcome}";
    }

    /// <summary>
    /// A flight that continues through bounces until the ball rolls to a stop: the flight model is stepped
    /// with fixed steps; a contact with the surface is located on each step's cubic Hermite interpolant
    /// (<see cref="HermiteSegment"/>), the bounce model is applied at that exact time, and stepping resumes
    /// from there for the rest of the step, so every call to <see cref="Step"/> still ends exactly one step
    /// later and the time grid of a fixed-step driver is kept. Allocates nothing after construction.
    /// </summary>
    /// <remarks>
    /// <para>Contact: the ball touches the surface plane when its centre is one radius above it (the contact
    /// point is centre - R n). Each bounce costs one extra derivative evaluation (at the post-bounce state)
    /// plus the integrator's evaluations for the remainder of the step.</para>
    /// <para>Rest condition: when the outgoing normal speed is below <see cref="RestNormalSpeed"/> (default
    /// 0.1 m/s: a hop of v^2/2g = 0.5 mm) on a surface that gravity presses it into, the ball stops bouncing and rolls
    /// (on a wall or a ceiling it never rests: it bounces and flies on). It keeps its angular momentum
    /// about the contact point, so it rolls at Lam/(1 + alpha) (the speed a sliding ball settles to when
    /// friction brings it to rolling); spin about the normal is kept. Rolling without slip, the ball is
    /// accelerated by the tangential part of the flight model's acceleration (the slope's gravity, drag, wind)
    /// divided by 1 + alpha, and slowed by rolling resistance c_rr g_n; it is stepped with Heun's method
    /// (exact on level ground in still air) and stops where its speed reaches zero, if the slope is too gentle
    /// to keep it moving. Wind is not considered when deciding that it can rest.
    /// Without a rest condition a ball with e_y &lt; 1 would bounce infinitely often in finite time.</para>
    /// <para>Not thread-safe: one per ball. The model, integrator and bounce model are shared, immutable.</para>
    /// </remarks>
    public sealed class BouncingFlight
    {
        /// <summary>The default rest condition: outgoing normal speed below 0.1 m/s (a hop of 0.5 mm) starts rolling.</summary>
        public const double DefaultRestNormalSpeed = 0.1;

        /// <summary>
        /// The default rolling-resistance coefficient, 0.03 (deceleration 0.03 g). A game value, not from a
        /// source: the references give none for a tennis ball on a court; tune it per surface.
        /// </summary>
        public const double DefaultRollingResistance = 0.03;

        /// <summary>
        /// The most Hermite pieces one step records for <see cref="StateAt"/>; also the most bounces one step
        /// takes (one fewer): a ball that would bounce more often in one step starts rolling, or on a surface
        /// gravity does not press it into (a wall), finishes the step without looking for more contacts.
        /// </summary>
        public const int MaxSegmentsPerStep = 16;

        private readonly HermiteSegment[] _segments = new HermiteSegment[MaxSegmentsPerStep];
        private readonly Plane _contactPlane;
        private readonly Vector3d _normal;
        private readonly double _radius;
        private readonly double _inertiaFactor;
        private readonly double _rollingDeceleration; // c_rr * g_n
        private readonly bool _canRest;  // the slope alone cannot keep the ball moving against rolling resistance
        private readonly bool _hasAero;
        private readonly bool _gravityHolds; // gravity pushes the ball into the surface: it can come to rest on it

        private FlightState _state;
        private StateDerivative _derivative;
        private FlightState _previous;
        private int _segmentCount;
        private FlightPhase _phase;
        private int _bounceCount;
        private BounceEvent _lastBounce;
        private long _derivativeEvaluations;

        /// <summary>Creates a bouncing flight.</summary>
        /// <param name="model">The flight model (its ball's radius and inertia factor are used at contact).</param>
        /// <param name="integrator">The integrator.</param>
        /// <param name="bounceModel">The contact model (for example <see cref="CrossBounce.Hard"/>).</param>
        /// <param name="plane">The surface's plane (a court: a point on it and its normal toward the ball, for example <see cref="Plane.Ground"/>). The ball touches it when its centre is one radius above it.</param>
        /// <param name="start">The launch state; finite; its centre should be more than one radius above the surface.</param>
        /// <param name="restNormalSpeed">Below this outgoing normal speed, m/s, the ball rolls instead of bouncing; finite and &gt;= 0.</param>
        /// <param name="rollingResistance">Rolling-resistance coefficient c_rr (deceleration c_rr g_n); finite and &gt;= 0.</param>
        /// <exception cref="ArgumentNullException">model, integrator or bounceModel is null.</exception>
        /// <exception cref="ArgumentException">The plane has a zero normal, the state is not finite, or a number is out of range.</exception>
        public BouncingFlight(
            FlightModel model,
            IIntegrator integrator,
            IBounceModel bounceModel,
            Plane plane,
            in FlightState start,
            double restNormalSpeed = DefaultRestNormalSpeed,
            double rollingResistance = DefaultRollingResistance)
        {
            Model = Require.NotNull(model, nameof(model));
            Integrator = Require.NotNull(integrator, nameof(integrator));
            BounceModel = Require.NotNull(bounceModel, nameof(bounceModel));
            Require.NonZero(plane.Normal, nameof(plane));
            RestNormalSpeed = Require.NonNegative(restNormalSpeed, nameof(restNormalSpeed));
            RollingResistance = Require.NonNegative(rollingResistance, nameof(rollingResistance));
            RequireFinite(start, nameof(start));

            Plane = plane;
            _normal = plane.Normal;
            _radius = model.Ball.Radius;
            _inertiaFactor = model.Ball.InertiaFactor;
            _contactPlane = new Plane(plane.Point + _normal * _radius, _normal);
            double gn = -Vector3d.Dot(model.Gravity, _normal);
            Vector3d gt = model.Gravity + _normal * gn;
            _rollingDeceleration = rollingResistance * Math.Max(gn, 0);
            _gravityHolds = gn > 0;
            _canRest = gt.Length / (1 + _inertiaFactor) <= _rollingDeceleration;
            _hasAero = model.Air.Density > 0 && (model.Drag != null || model.Lift != null);
            Reset(start);
        }

        /// <summary>The flight model.</summary>
        public FlightModel Model { get; }

        /// <summary>The integrator.</summary>
        public IIntegrator Integrator { get; }

        /// <summary>The contact model.</summary>
        public IBounceModel BounceModel { get; }

        /// <summary>The surface's plane.</summary>
        public Plane Plane { get; }

        /// <summary>Below this outgoing normal speed, m/s, a bounce turns into rolling.</summary>
        public double RestNormalSpeed { get; }

        /// <summary>The rolling-resistance coefficient.</summary>
        public double RollingResistance { get; }

        /// <summary>The current state (the end of the last step).</summary>
        public FlightState State => _state;

        /// <summary>The derivative at the current state: the flight model's while flying, the rolling motion's otherwise.</summary>
        public StateDerivative Derivative => _derivative;

        /// <summary>The state at the start of the last step.</summary>
        public FlightState PreviousState => _previous;

        /// <summary>Flying, rolling or stopped.</summary>
        public FlightPhase Phase => _phase;

        /// <summary>Bounces since the last <see cref="Reset"/>.</summary>
        public int BounceCount => _bounceCount;

        /// <summary>The latest bounce (default when <see cref="BounceCount"/> is 0).</summary>
        public BounceEvent LastBounce => _lastBounce;

        /// <summary>Derivative evaluations of the flight model since the last <see cref="Reset"/>, the one at the start state included.</summary>
        public long DerivativeEvaluations => _derivativeEvaluations;

        /// <summary>
        /// Starts again from <paramref name="start"/>: flying, or rolling when the ball is placed on the surface
        /// (centre at most one radius above it) without moving away from it, where gravity presses it into the surface.
        /// </summary>
        /// <param name="start">The launch state; every component finite.</param>
        /// <exception cref="ArgumentException">The state is not finite (nothing is changed).</exception>
        public void Reset(in FlightState start)
        {
            RequireFinite(start, nameof(start));
            _state = start;
            _derivative = Model.Derivative(start);
            _derivativeEvaluations = 1;
            _previous = start;
            _segmentCount = 0;
            _phase = FlightPhase.Flying;
            _bounceCount = 0;
            _lastBounce = default;
            if (_gravityHolds && _contactPlane.SignedDistance(start.Position) <= 0 && Vector3d.Dot(start.Velocity, _normal) <= 0)
            {
                // Placed on the surface (or in it) and not leaving it: it rolls from there, or rests.
                StartRolling(_contactPlane.Project(start.Position), start.Velocity, start.AngularVelocity, start.Time);
            }
        }

        /// <summary>
        /// Advances the ball by exactly <paramref name="step"/> seconds, through any bounces inside the step,
        /// and writes those bounces into <paramref name="bounces"/> in time order. Allocates nothing.
        /// </summary>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="bounces">Where to write the step's bounces; those that do not fit are still applied (see <see cref="LastBounce"/>).</param>
        /// <returns>The number of bounces inside the step (may exceed <paramref name="bounces"/>' length).</returns>
        /// <exception cref="ArgumentOutOfRangeException">The step is not finite and positive (nothing is changed).</exception>
        /// <exception cref="InvalidOperationException">
        /// The step diverged (the integrator produced a non-finite state: the step is far beyond its stability
        /// limit for this ball and speed; use <see cref="MagnusBall.Integration.StableIntegrator"/> or a smaller
        /// step). The ball's state, phase and counts are left as they were before the call.
        /// </exception>
        public int Step(double step, Span<BounceEvent> bounces)
        {
            Require.Step(step, nameof(step));
            FlightState savedState = _state, savedPrevious = _previous;
            StateDerivative savedDerivative = _derivative;
            int savedBounceCount = _bounceCount;
            BounceEvent savedLastBounce = _lastBounce;
            long savedEvaluations = _derivativeEvaluations;
            double endTime = _state.Time + step;
            _previous = _state;
            _segmentCount = 0;
            int found = 0;

            while (_phase == FlightPhase.Flying)
            {
                double h = endTime - _state.Time;
                if (!(_state.Time + h > _state.Time))
                {
                    // Less than one ulp of time left after a bounce: nothing to integrate.
                    break;
                }

                FlightState next = Integrator.Step(Model, _state, _derivative, h, out StateDerivative nextDerivative, out int evaluations);
                if (!next.IsFinite || !nextDerivative.Acceleration.IsFinite || !nextDerivative.AngularAcceleration.IsFinite)
                {
                    // Only flying sub-steps can diverge, so the phase is still Flying: put back what this call changed.
                    _state = savedState;
                    _previous = savedPrevious;
                    _derivative = savedDerivative;
                    _bounceCount = savedBounceCount;
                    _lastBounce = savedLastBounce;
                    _derivativeEvaluations = savedEvaluations;
                    _segmentCount = 0;
                    throw new InvalidOperationException(
                        $"The step of {Require.Format(h)} s diverged (the state would not be finite): it is beyond {Integrator.Name}'s " +
                        "stability limit for this ball and speed. Use StableIntegrator.RungeKutta4 or a smaller step.");
                }

                _derivativeEvaluations += evaluations;
                var segment = new HermiteSegment(_state, _derivative, next, nextDerivative);
                if (found >= MaxSegmentsPerStep - 1 || !segment.TryFindCrossing(_contactPlane, CrossingDirection.AgainstNormal, out double contactTime))
                {
                    AddSegment(segment);
                    _state = new FlightState(next.Position, next.Velocity, next.AngularVelocity, endTime);
                    _derivative = nextDerivative;
                    break;
                }

                // The bounce, at the located time, on the interpolant; the centre is put exactly on the contact plane.
                FlightState touching = segment.StateAt(contactTime);
                Vector3d centre = _contactPlane.Project(touching.Position);
                AddSegment(contactTime > segment.StartTime ? Truncated(segment, contactTime) : default);
                BounceOutcome outcome = BounceModel.Bounce(Model.Ball, _normal, touching.Velocity, touching.AngularVelocity);
                double outgoingNormalSpeed = Vector3d.Dot(outcome.Velocity, _normal);
                // Rest only where gravity holds the ball on the surface (a floor or a slope, not a wall or a ceiling).
                bool roll = _gravityHolds &&
                    (outcome.Regime == BounceRegime.None || outgoingNormalSpeed < RestNormalSpeed || found >= MaxSegmentsPerStep - 2);
                _bounceCount++;
                _lastBounce = new BounceEvent(
                    _bounceCount, contactTime, centre, centre - _normal * _radius, touching.Velocity, touching.AngularVelocity, outcome, roll);
                if (found < bounces.Length)
                {
                    bounces[found] = _lastBounce;
                }

                found++;
                if (roll)
                {
                    StartRolling(centre, outcome.Velocity, outcome.AngularVelocity, contactTime);
                    break;
                }

                _state = new FlightState(centre, outcome.Velocity, outcome.AngularVelocity, contactTime);
                _derivative = Model.Derivative(_state);
                _derivativeEvaluations++;
            }

            if (_phase != FlightPhase.Flying)
            {
                Roll(endTime);
            }
            else if (_state.Time != endTime)
            {
                _state = new FlightState(_state.Position, _state.Velocity, _state.AngularVelocity, endTime);
            }

            return found;
        }

        /// <summary>
        /// The ball's state at <paramref name="time"/> inside the last step (between <see cref="PreviousState"/>
        /// and <see cref="State"/>), from the cubic Hermite pieces of the step split at its bounces: what a
        /// renderer should draw, without cutting a bounce's corner.
        /// </summary>
        /// <param name="time">A time, s; clamped to the last step.</param>
        public FlightState StateAt(double time)
        {
            if (_segmentCount == 0 || time >= _state.Time)
            {
                return _state;
            }

            if (time <= _previous.Time)
            {
                return _previous;
            }

            for (int i = 0; i < _segmentCount; i++)
            {
                HermiteSegment segment = _segments[i];
                if (segment.Duration > 0 && time <= segment.EndTime)
                {
                    return time < segment.StartTime ? segment.Start : segment.StateAt(time);
                }
            }

            return _state;
        }

        private void StartRolling(in Vector3d centre, in Vector3d velocity, in Vector3d angularVelocity, double time)
        {
            // Keep the angular momentum about the contact point: roll at Lam / (1 + alpha), Lam = vt - alpha R (n x w).
            Vector3d vt = velocity - _normal * Vector3d.Dot(velocity, _normal);
            Vector3d lambda = vt - Vector3d.Cross(_normal, angularVelocity) * (_radius * _inertiaFactor);
            Vector3d rolling = lambda / (1 + _inertiaFactor);
            Vector3d spinNormal = _normal * Vector3d.Dot(angularVelocity, _normal);
            _phase = FlightPhase.Rolling;
            SetRolling(new FlightState(centre, rolling, RollingSpin(rolling, spinNormal), time));
        }

        private void Roll(double endTime)
        {
            if (_phase == FlightPhase.Rolling && _state.Time < endTime)
            {
                // Heun's method (exact for a constant acceleration, so exact on level ground in still air), with
                // the stop located inside the step where the speed along the motion reaches zero.
                double h = endTime - _state.Time;
                FlightState s0 = _state;
                Vector3d v0 = s0.Velocity;
                Vector3d spinNormal = _normal * Vector3d.Dot(s0.AngularVelocity, _normal);
                Vector3d a0 = _derivative.Acceleration;
                Vector3d vPredicted = v0 + a0 * h;
                if (_canRest && (v0.LengthSquared == 0 || Vector3d.Dot(vPredicted, v0) <= 0))
                {
                    StopWithin(s0, a0, vPredicted, h, spinNormal, endTime);
                    return;
                }

                var predicted = new FlightState(s0.Position + v0 * h, vPredicted, RollingSpin(vPredicted, spinNormal), endTime);
                Vector3d a1 = RollingAcceleration(predicted);
                Vector3d average = (a0 + a1) * 0.5;
                Vector3d v1 = v0 + average * h;
                if (_canRest && Vector3d.Dot(v1, v0) <= 0)
                {
                    StopWithin(s0, average, v1, h, spinNormal, endTime);
                    return;
                }

                var next = new FlightState(_contactPlane.Project(s0.Position + (v0 + v1) * (0.5 * h)), v1, RollingSpin(v1, spinNormal), endTime);
                var nextDerivative = new StateDerivative(v1, RollingAcceleration(next), Vector3d.Zero);
                AddSegment(new HermiteSegment(s0, _derivative, next, nextDerivative));
                _state = next;
                _derivative = nextDerivative;
                return;
            }

            if (_phase == FlightPhase.Stopped)
            {
                _state = new FlightState(_state.Position, Vector3d.Zero, _state.AngularVelocity, endTime);
            }
        }

        /// <summary>Stops the ball where its speed along the motion, changing at <paramref name="a"/>, reaches zero.</summary>
        private void StopWithin(in FlightState s0, in Vector3d a, in Vector3d v1, double h, in Vector3d spinNormal, double endTime)
        {
            Vector3d v0 = s0.Velocity;
            double speed = v0.Length;
            double along = speed > 0 ? Vector3d.Dot(v1, v0) / speed : 0;
            double stopAfter = speed > 0 ? h * speed / (speed - along) : 0;
            Vector3d position = _contactPlane.Project(s0.Position + v0 * stopAfter + a * (0.5 * stopAfter * stopAfter));
            var stopped = new FlightState(position, Vector3d.Zero, spinNormal, s0.Time + stopAfter);
            if (stopped.Time > s0.Time)
            {
                AddSegment(new HermiteSegment(s0, _derivative, stopped, new StateDerivative(Vector3d.Zero, a, Vector3d.Zero)));
            }

            _phase = FlightPhase.Stopped;
            _state = new FlightState(position, Vector3d.Zero, spinNormal, endTime);
            _derivative = default;
        }

        private void SetRolling(in FlightState state)
        {
            _state = state;
            _derivative = new StateDerivative(state.Velocity, RollingAcceleration(state), Vector3d.Zero);
        }

        /// <summary>
        /// Acceleration of a ball rolling without slip: the tangential part of the flight model's acceleration
        /// (gravity along the slope, drag; the Magnus force of rolling spin is normal to the surface) divided by
        /// 1 + alpha, minus rolling resistance c_rr g_n along the motion.
        /// </summary>
        private Vector3d RollingAcceleration(in FlightState state)
        {
            Vector3d a = Model.Gravity;
            if (_hasAero)
            {
                a = Model.Derivative(state).Acceleration;
                _derivativeEvaluations++;
            }

            Vector3d tangential = a - _normal * Vector3d.Dot(a, _normal);
            return tangential * (1.0 / (1 + _inertiaFactor)) - state.Velocity.NormalizedOrZero() * _rollingDeceleration;
        }

        /// <summary>The angular velocity of rolling without slip at velocity v: w = (n x v)/R, plus the kept spin about n.</summary>
        private Vector3d RollingSpin(in Vector3d velocity, in Vector3d spinNormal) => Vector3d.Cross(_normal, velocity) * (1.0 / _radius) + spinNormal;

        private void AddSegment(in HermiteSegment segment)
        {
            if (_segmentCount < MaxSegmentsPerStep && segment.Duration > 0)
            {
                _segments[_segmentCount++] = segment;
            }
        }

        /// <summary>The part of a segment up to <paramref name="time"/>, re-expressed as its own Hermite piece.</summary>
        private static HermiteSegment Truncated(in HermiteSegment segment, double time)
        {
            // The cubic restricted to [t0, tc] is again a cubic Hermite with the interpolant's own end values and
            // slopes; slopes are taken by differentiating the position and velocity cubics (exact for a cubic).
            double h = segment.Duration;
            double s = (time - segment.StartTime) / h;
            FlightState end = segment.StateAt(time);
            var endDerivative = new StateDerivative(
                CubicSlope(segment.Start.Position, segment.StartDerivative.Velocity * h, segment.End.Position, segment.EndDerivative.Velocity * h, s) / h,
                CubicSlope(segment.Start.Velocity, segment.StartDerivative.Acceleration * h, segment.End.Velocity, segment.EndDerivative.Acceleration * h, s) / h,
                CubicSlope(segment.Start.AngularVelocity, segment.StartDerivative.AngularAcceleration * h, segment.End.AngularVelocity,
                    segment.EndDerivative.AngularAcceleration * h, s) / h);
            return new HermiteSegment(segment.Start, segment.StartDerivative, end, endDerivative);
        }

        private static Vector3d CubicSlope(in Vector3d y0, in Vector3d m0, in Vector3d y1, in Vector3d m1, double s)
        {
            double s2 = s * s;
            double d00 = 6 * s2 - 6 * s;
            double d10 = 3 * s2 - 4 * s + 1;
            double d01 = 6 * s - 6 * s2;
            double d11 = 3 * s2 - 2 * s;
            return y0 * d00 + m0 * d10 + y1 * d01 + m1 * d11;
        }

        private static void RequireFinite(in FlightState state, string name)
        {
            if (!state.IsFinite)
            {
                throw new ArgumentException($"{name} must have finite position, velocity, angular velocity and time; got {state}.", name);
            }
        }
    }
}
