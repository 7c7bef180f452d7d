using System;
using MagnusBall.Contact;

namespace MagnusBall.Flight
{
    /// <summary>
    /// A surface the ball bounces on and rolls over: the plane, the bounce law, and when the ball stops flying
    /// (rolls) and stops rolling (rests). Given to a <see cref="FlightStepper"/>, it turns touching the plane from
    /// a landing into a <see cref="FlightEventKinds.Bounce"/> and, after the last bounce, a roll to a
    /// <see cref="FlightEventKinds.Rest"/>. Immutable; share it between balls.
    /// </summary>
    public sealed class GroundContact
    {
        /// <summary>Default outgoing normal speed, m/s, below which the ball rolls instead of bouncing again (0.1 m/s).</summary>
        internal const double DefaultRestNormalSpeed = 0.1;

        /// <summary>
        /// Default rolling-resistance coefficient c_rr (0.03): a game value with no published source, in the range of
        /// a tennis ball on a hard court. The rolling ball decelerates at c_rr times the gravity along the normal.
        /// </summary>
        internal const double DefaultRollingResistance = 0.03;

        /// <summary>Creates a contact surface.</summary>
        /// <param name="bounce">The bounce law (for example <see cref="CrossBounce.Hard"/>).</param>
        /// <param name="plane">The surface; the ball bounces when its surface (its centre one radius above the plane) touches it.</param>
        /// <param name="restNormalSpeed">Outgoing normal speed below which the ball rolls, m/s; finite, &gt;= 0.</param>
        /// <param name="rollingResistance">Rolling-resistance coefficient c_rr, the deceleration over the normal gravity (a = c_rr g_n);
        /// finite, &gt;= 0. A coefficient defined by a resisting force whose work is the rolling ball's lost kinetic energy
        /// decelerates by c_rr g_n / (1 + alpha): divide it by 1 + alpha (the ball's inertia factor plus one) first.</param>
        /// <exception cref="ArgumentException">bounce is null, the plane's normal is zero or not finite, or a number is out of range.</exception>
        public GroundContact(
            IBounceModel bounce, Plane plane, double restNormalSpeed = DefaultRestNormalSpeed, double rollingResistance = DefaultRollingResistance)
        {
            Bounce = Require.NotNull(bounce, nameof(bounce));
            Require.Finite(plane.Point, nameof(plane));
            Require.NonZero(plane.Normal, nameof(plane));
            Plane = plane;
            RestNormalSpeed = Require.NonNegative(restNormalSpeed, nameof(restNormalSpeed));
            RollingResistance = Require.NonNegative(rollingResistance, nameof(rollingResistance));
        }

        /// <summary>The bounce law.</summary>
        internal IBounceModel Bounce { get; }

        /// <summary>The surface plane (its normal points out of the surface, toward the ball).</summary>
        internal Plane Plane { get; }

        /// <summary>Outgoing normal speed below which the ball rolls, m/s.</summary>
        internal double RestNormalSpeed { get; }

        /// <summary>Rolling-resistance coefficient c_rr: the rolling ball decelerates at c_rr times the gravity along the normal.</summary>
        internal double RollingResistance { get; }
    }
}
