using System.Runtime.CompilerServices;

namespace MagnusBall
{
    /// <summary>
    /// The state of a ball in flight at one instant: position (m), velocity (m/s), angular velocity (rad/s)
    /// and time (s). Nine numbers of state: the thesis's six-state ODE (position, velocity) plus the spin,
    /// so that spin decay can be integrated with the flight.
    /// </summary>
    /// <remarks>Source: Agrawal (2023), "Magnus Effect In Video Games", eqs. (12)-(15).</remarks>
    public readonly struct FlightState
    {
        /// <summary>Position of the ball's centre, m.</summary>
        public readonly Vector3d Position;

        /// <summary>Velocity of the ball's centre relative to the ground frame, m/s.</summary>
        public readonly Vector3d Velocity;

        /// <summary>Angular velocity of the ball, rad/s, in the frame's own rotation convention.</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>Time, s.</summary>
        public readonly double Time;

        /// <summary>Creates a state. Use <see cref="Create"/> to validate the values.</summary>
        /// <param name="position">Position, m.</param>
        /// <param name="velocity">Velocity, m/s.</param>
        /// <param name="angularVelocity">Angular velocity, rad/s.</param>
        /// <param name="time">Time, s.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public FlightState(in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, double time = 0)
        {
            Position = position;
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Time = time;
        }

        /// <summary>
        /// Creates a state after checking that every number is finite.
        /// </summary>
        /// <param name="position">Position, m (finite).</param>
        /// <param name="velocity">Velocity, m/s (finite).</param>
        /// <param name="angularVelocity">Angular velocity, rad/s (finite).</param>
        /// <param name="time">Time, s (finite).</param>
        /// <exception cref="System.ArgumentException">A component is NaN or infinite; the message names it.</exception>
        internal static FlightState Create(Vector3d position, Vector3d velocity, Vector3d angularVelocity, double time = 0)
        {
            Require.Finite(position, nameof(position));
            Require.Finite(velocity, nameof(velocity));
            Require.Finite(angularVelocity, nameof(angularVelocity));
            Require.Finite(time, nameof(time));
            return new FlightState(position, velocity, angularVelocity, time);
        }

        /// <summary>True when every component, and the time, is finite.</summary>
        public bool IsFinite
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => Position.IsFinite && Velocity.IsFinite && AngularVelocity.IsFinite && double.IsFinite(Time);
        }

        /// <summary>The state advanced along a derivative: <c>this + h * k</c>, with time <c>Time + h</c>.</summary>
        /// <param name="k">The derivative (rate of change of every component).</param>
        /// <param name="h">How far to go, s.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal FlightState Advance(in StateDerivative k, double h) => new FlightState(
            new Vector3d(Position.X + h * k.Velocity.X, Position.Y + h * k.Velocity.Y, Position.Z + h * k.Velocity.Z),
            new Vector3d(Velocity.X + h * k.Acceleration.X, Velocity.Y + h * k.Acceleration.Y, Velocity.Z + h * k.Acceleration.Z),
            new Vector3d(
                AngularVelocity.X + h * k.AngularAcceleration.X,
                AngularVelocity.Y + h * k.AngularAcceleration.Y,
                AngularVelocity.Z + h * k.AngularAcceleration.Z),
            Time + h);

        /// <summary>A copy with another angular velocity.</summary>
        /// <param name="angularVelocity">The new angular velocity, rad/s.</param>
        public FlightState WithAngularVelocity(in Vector3d angularVelocity) => new FlightState(Position, Velocity, angularVelocity, Time);

        /// <inheritdoc />
        public override string ToString() => $"t={Time:R} p={Position} v={Velocity} w={AngularVelocity}";
    }

    /// <summary>
    /// The time derivative of a <see cref="FlightState"/>: d(position)/dt, d(velocity)/dt and d(angular velocity)/dt.
    /// One evaluation of <see cref="FlightModel.Derivative"/> produces one of these.
    /// </summary>
    public readonly struct StateDerivative
    {
        /// <summary>d(position)/dt, m/s: the velocity.</summary>
        public readonly Vector3d Velocity;

        /// <summary>d(velocity)/dt, m/s^2: the sum of gravity, drag and Magnus accelerations.</summary>
        public readonly Vector3d Acceleration;

        /// <summary>d(angular velocity)/dt, rad/s^2: the spin-decay rate.</summary>
        public readonly Vector3d AngularAcceleration;

        /// <summary>Creates a derivative.</summary>
        /// <param name="velocity">d(position)/dt, m/s.</param>
        /// <param name="acceleration">d(velocity)/dt, m/s^2.</param>
        /// <param name="angularAcceleration">d(angular velocity)/dt, rad/s^2.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public StateDerivative(in Vector3d velocity, in Vector3d acceleration, in Vector3d angularAcceleration)
        {
            Velocity = velocity;
            Acceleration = acceleration;
            AngularAcceleration = angularAcceleration;
        }

        /// <summary>True when every component is finite.</summary>
        internal bool IsFinite
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => Velocity.IsFinite && Acceleration.IsFinite && AngularAcceleration.IsFinite;
        }

        /// <inheritdoc />
        public override string ToString() => $"dp={Velocity} dv={Acceleration} dw={AngularAcceleration}";
    }
}
