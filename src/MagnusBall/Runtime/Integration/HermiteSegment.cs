// HermiteSegment: one step's cubic Hermite dense output (its ends, the state at a time, cutting it at a time). The
// event searches on it, plane crossings and the apex with their quick tests and root refinement, are in
// HermiteSegment.Crossings.cs.
using System;
using System.Runtime.CompilerServices;

namespace MagnusBall.Integration
{
    /// <summary>Which way a crossing of a <see cref="Plane"/> goes.</summary>
    internal enum CrossingDirection
    {
        /// <summary>From the negative side to the positive side (along the normal): passing a net or goal line.</summary>
        AlongNormal = 0,

        /// <summary>From the positive side to the negative side (against the normal): landing on the ground.</summary>
        AgainstNormal = 1,
    }

    /// <summary>
    /// Dense output for one integrator step: the cubic Hermite interpolants of position, velocity and
    /// angular velocity built from the states and derivatives at both ends of the step. Costs no extra
    /// derivative evaluation (the end derivative is the next step's start derivative).
    /// </summary>
    /// <remarks>
    /// <para>Position uses p and dp/dt = v at both ends; velocity uses v and dv/dt = a at both ends; angular
    /// velocity uses w and dw/dt. Each interpolant matches its value and slope at both ends, so its local
    /// error is O(h^4) and an event located on it keeps the order of a fourth-order method (Hairer, Norsett
    /// &amp; Wanner, "Solving ODEs I", section II.6, dense output by Hermite interpolation). Because velocity
    /// has its own interpolant, <see cref="VelocityAt"/> is not exactly the time derivative of
    /// <see cref="PositionAt"/>; both are accurate to the interpolant's order.</para>
    /// <para>Events are roots of a scalar cubic in the step: the signed distance to a plane (position
    /// interpolant) or the velocity along "up" (velocity interpolant, for the apex). The cubic is split at its
    /// turning points into monotone pieces, the first piece with the wanted sign change is taken, and its root
    /// is found by safeguarded Newton-bisection to <see cref="TimeTolerance"/>. So the first crossing inside
    /// the step is found even when both ends of the step are on the same side.</para>
    /// </remarks>
    internal readonly partial struct HermiteSegment : IDenseOutput
    {
        /// <summary>Events are located to this time tolerance, s (1e-12 s).</summary>
        public const double TimeTolerance = 1e-12;

        /// <summary>The state at the start of the step.</summary>
        public readonly FlightState Start;

        /// <summary>The derivative at the start of the step (model.Derivative(Start)).</summary>
        public readonly StateDerivative StartDerivative;

        /// <summary>The state at the end of the step.</summary>
        public readonly FlightState End;

        /// <summary>The derivative at the end of the step (model.Derivative(End)).</summary>
        public readonly StateDerivative EndDerivative;

        /// <summary>Creates the segment of one step from its end states and derivatives.</summary>
        /// <param name="start">State at the start of the step.</param>
        /// <param name="startDerivative">Derivative at the start of the step.</param>
        /// <param name="end">State at the end of the step; its time must be later than the start's.</param>
        /// <param name="endDerivative">Derivative at the end of the step.</param>
        /// <exception cref="ArgumentException">
        /// The end is not later than the start, a time is not finite, or a state or derivative has a non-finite
        /// component (for example a step that diverged); the message names which.
        /// </exception>
        public HermiteSegment(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative)
        {
            RequireFinite(start, nameof(start));
            RequireFinite(startDerivative, nameof(startDerivative));
            RequireFinite(end, nameof(end));
            RequireFinite(endDerivative, nameof(endDerivative));
            if (!double.IsFinite(start.Time) || !double.IsFinite(end.Time) || !(end.Time > start.Time))
            {
                throw new ArgumentException(
                    $"end.Time must be finite and later than start.Time; got start {Require.Format(start.Time)} s, end {Require.Format(end.Time)} s.",
                    nameof(end));
            }

            Start = start;
            StartDerivative = startDerivative;
            End = end;
            EndDerivative = endDerivative;
        }

        // The flight core's constructor: its states and derivatives are already known finite and its end later than its
        // start (FlightStepper.Takes), so the four checks above would only repeat them on every step. Called with new on a
        // local (not through OfTakenStep), the segment is built in place: no temporary to zero and copy.
        internal HermiteSegment(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative, bool trusted)
        {
            Start = start;
            StartDerivative = startDerivative;
            End = end;
            EndDerivative = endDerivative;
        }

        /// <summary>The segment of a step the flight core has taken (Flight.FlightStepper.Takes): no checks.</summary>
        internal static HermiteSegment OfTakenStep(in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative) =>
            new HermiteSegment(start, startDerivative, end, endDerivative, trusted: true);

        /// <summary>Time at the start of the step, s.</summary>
        public double StartTime => Start.Time;

        /// <summary>Time at the end of the step, s.</summary>
        public double EndTime => End.Time;

        /// <summary>Length of the step, s.</summary>
        public double Duration => End.Time - Start.Time;

        /// <summary>Interpolated position at <paramref name="time"/>, m (exact at both ends; extrapolates outside).</summary>
        /// <param name="time">Time, s; normally inside [StartTime, EndTime].</param>
        public Vector3d PositionAt(double time)
        {
            double h = Duration;
            if (!(h > 0))
            {
                return Start.Position; // the default segment (no step yet)
            }

            return Cubic(Start.Position, StartDerivative.Velocity, End.Position, EndDerivative.Velocity, h, (time - Start.Time) / h);
        }

        /// <summary>Interpolated velocity at <paramref name="time"/>, m/s (its own Hermite cubic from v and a).</summary>
        /// <param name="time">Time, s; normally inside [StartTime, EndTime].</param>
        public Vector3d VelocityAt(double time)
        {
            double h = Duration;
            if (!(h > 0))
            {
                return Start.Velocity;
            }

            return Cubic(Start.Velocity, StartDerivative.Acceleration, End.Velocity, EndDerivative.Acceleration, h, (time - Start.Time) / h);
        }

        /// <summary>Interpolated angular velocity at <paramref name="time"/>, rad/s.</summary>
        /// <param name="time">Time, s; normally inside [StartTime, EndTime].</param>
        public Vector3d AngularVelocityAt(double time)
        {
            double h = Duration;
            if (!(h > 0))
            {
                return Start.AngularVelocity;
            }

            return Cubic(Start.AngularVelocity, StartDerivative.AngularAcceleration, End.AngularVelocity, EndDerivative.AngularAcceleration, h, (time - Start.Time) / h);
        }

        /// <summary>The full interpolated state at <paramref name="time"/> (position, velocity, spin, time).</summary>
        /// <param name="time">Time, s; finite, normally inside [StartTime, EndTime].</param>
        /// <exception cref="System.ArgumentException">The time is not finite; the message names it.</exception>
        public FlightState StateAt(double time)
        {
            Require.Finite(time, nameof(time));
            if (time == Start.Time || !(Duration > 0))
            {
                return Start;
            }

            if (time == End.Time)
            {
                return End;
            }

            return new FlightState(PositionAt(time), VelocityAt(time), AngularVelocityAt(time), time);
        }

        private static void RequireFinite(in FlightState state, string name) => Require.FiniteState(state, name);

        private static void RequireFinite(in StateDerivative derivative, string name)
        {
            if (!derivative.Velocity.IsFinite || !derivative.Acceleration.IsFinite || !derivative.AngularAcceleration.IsFinite)
            {
                throw new ArgumentException(
                    $"{name} must have finite velocity, acceleration and angular acceleration; got v={derivative.Velocity}, a={derivative.Acceleration}, dw/dt={derivative.AngularAcceleration}.",
                    name);
            }
        }

        /// <summary>
        /// This segment cut at <paramref name="time"/>: the cubic restricted to [StartTime, time], which is again a cubic
        /// Hermite with the interpolant's own end value and slope there (slopes by differentiating the cubic, exact; no
        /// evaluation). Default (zero duration) when the time is not after the start.
        /// </summary>
        /// <summary>
        /// <see cref="Until"/>, or false when the cut's end state or slope is not finite (the cubic of an extreme but finite
        /// step can overflow between its ends; the stepper then refuses the step instead of throwing from inside it).
        /// </summary>
        internal bool TryUntil(double time, out HermiteSegment cut)
        {
            cut = default;
            double h = Duration;
            if (!(time > StartTime) || !(h > 0))
            {
                return true;
            }

            if (time >= EndTime)
            {
                cut = this;
                return true;
            }

            double s = (time - StartTime) / h;
            FlightState end = StateAt(time);
            var endDerivative = new StateDerivative(
                CubicSlope(Start.Position, StartDerivative.Velocity * h, End.Position, EndDerivative.Velocity * h, s) / h,
                CubicSlope(Start.Velocity, StartDerivative.Acceleration * h, End.Velocity, EndDerivative.Acceleration * h, s) / h,
                CubicSlope(Start.AngularVelocity, StartDerivative.AngularAcceleration * h, End.AngularVelocity, EndDerivative.AngularAcceleration * h, s) / h);
            if (!end.IsFinite || !endDerivative.IsFinite || !(end.Time > Start.Time))
            {
                return false;
            }

            cut = new HermiteSegment(Start, StartDerivative, end, endDerivative);
            return true;
        }

        internal HermiteSegment Until(double time)
        {
            double h = Duration;
            if (!(time > StartTime) || !(h > 0))
            {
                return default;
            }

            if (time >= EndTime)
            {
                return this;
            }

            double s = (time - StartTime) / h;
            FlightState end = StateAt(time);
            var endDerivative = new StateDerivative(
                CubicSlope(Start.Position, StartDerivative.Velocity * h, End.Position, EndDerivative.Velocity * h, s) / h,
                CubicSlope(Start.Velocity, StartDerivative.Acceleration * h, End.Velocity, EndDerivative.Acceleration * h, s) / h,
                CubicSlope(Start.AngularVelocity, StartDerivative.AngularAcceleration * h, End.AngularVelocity, EndDerivative.AngularAcceleration * h, s) / h);
            return new HermiteSegment(Start, StartDerivative, end, endDerivative);
        }

        // The slope (times h) of the cubic Hermite at fraction s, for a cut's end. A component that overflows although its
        // inputs are finite (ends near 1e308: y0 d00 and y1 d01 are each up to 1.5 |y|, and cancel, inf - inf) is evaluated
        // again with its inputs scaled by 2^-600 and the result scaled back (infinite only where the slope itself exceeds a
        // double). Finite results are the plain formula's, bit for bit.
        private static Vector3d CubicSlope(in Vector3d y0, in Vector3d m0, in Vector3d y1, in Vector3d m1, double s)
        {
            double s2 = s * s;
            double d00 = 6 * s2 - 6 * s;
            double d10 = 3 * s2 - 4 * s + 1;
            double d01 = 6 * s - 6 * s2;
            double d11 = 3 * s2 - 2 * s;
            double x = y0.X * d00 + m0.X * d10 + y1.X * d01 + m1.X * d11;
            double y = y0.Y * d00 + m0.Y * d10 + y1.Y * d01 + m1.Y * d11;
            double z = y0.Z * d00 + m0.Z * d10 + y1.Z * d01 + m1.Z * d11;
            if (!double.IsFinite(x + y + z))
            {
                x = double.IsFinite(x) ? x : ScaledSlope(d00, d10, d01, d11, y0.X, m0.X, y1.X, m1.X);
                y = double.IsFinite(y) ? y : ScaledSlope(d00, d10, d01, d11, y0.Y, m0.Y, y1.Y, m1.Y);
                z = double.IsFinite(z) ? z : ScaledSlope(d00, d10, d01, d11, y0.Z, m0.Z, y1.Z, m1.Z);
            }

            return new Vector3d(x, y, z);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double ScaledSlope(double d00, double d10, double d01, double d11, double y0, double m0, double y1, double m1)
        {
            const double Down = 2.409919865102884e-181; // 2^-600
            const double Up = 4.149515568880993e+180;    // 2^600
            return ((y0 * Down) * d00 + (m0 * Down) * d10 + (y1 * Down) * d01 + (m1 * Down) * d11) * Up;
        }

        // The cubic Hermite through (y0, d0) and (y1, d1) over a step h, at fraction s. A component that overflows although
        // its ends are finite (values near double.MaxValue, or slopes whose d h overflows) is evaluated again with every
        // input scaled by 2^-600 and the result scaled back; where the interpolated value itself exceeds double.MaxValue
        // it is held at +-double.MaxValue. Finite results are the plain formula's, bit for bit.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d Cubic(in Vector3d y0, in Vector3d d0, in Vector3d y1, in Vector3d d1, double h, double s)
        {
            double s2 = s * s;
            double s3 = s2 * s;
            double h00 = 2 * s3 - 3 * s2 + 1;
            double h10 = s3 - 2 * s2 + s;
            double h01 = 3 * s2 - 2 * s3;
            double h11 = s3 - s2;
            double x = h00 * y0.X + h10 * (d0.X * h) + h01 * y1.X + h11 * (d1.X * h);
            double y = h00 * y0.Y + h10 * (d0.Y * h) + h01 * y1.Y + h11 * (d1.Y * h);
            double z = h00 * y0.Z + h10 * (d0.Z * h) + h01 * y1.Z + h11 * (d1.Z * h);
            if (!double.IsFinite(x + y + z))
            {
                x = double.IsFinite(x) ? x : Scaled(h00, h10, h01, h11, y0.X, d0.X, y1.X, d1.X, h);
                y = double.IsFinite(y) ? y : Scaled(h00, h10, h01, h11, y0.Y, d0.Y, y1.Y, d1.Y, h);
                z = double.IsFinite(z) ? z : Scaled(h00, h10, h01, h11, y0.Z, d0.Z, y1.Z, d1.Z, h);
            }

            return new Vector3d(x, y, z);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double Scaled(double h00, double h10, double h01, double h11, double y0, double d0, double y1, double d1, double h)
        {
            const double Down = 2.409919865102884e-181; // 2^-600
            const double Up = 4.149515568880993e+180;    // 2^600
            double value = h00 * (y0 * Down) + h10 * ((d0 * Down) * h) + h01 * (y1 * Down) + h11 * ((d1 * Down) * h);
            value *= Up;
            // Still beyond double.MaxValue (or its terms are): the cubic between two finite ends overshoots what a double
            // holds; the nearest finite value is given, so a state read between finite ends stays finite.
            return value >= double.MaxValue || double.IsNaN(value) && h10 * d0 + h11 * d1 > 0 ? double.MaxValue
                : value <= -double.MaxValue || double.IsNaN(value) ? -double.MaxValue : value;
        }
    }
}
