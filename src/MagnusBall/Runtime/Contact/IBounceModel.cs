using System.Runtime.CompilerServices;

namespace MagnusBall.Contact
{
    /// <summary>
    /// A contact model: what a ball's velocity and spin become when it bounces off a surface. Implementations
    /// are immutable, thread-safe and allocate nothing per bounce.
    /// </summary>
    public interface IBounceModel
    {
        /// <summary>
        /// The ball's velocity and angular velocity just after a bounce, from those just before.
        /// </summary>
        /// <param name="ball">The ball (radius and moment-of-inertia factor matter); not null.</param>
        /// <param name="normal">The surface normal, pointing out of the surface toward the ball; finite, non-zero (it is normalised).</param>
        /// <param name="velocity">The ball's velocity before the bounce, m/s; finite.</param>
        /// <param name="angularVelocity">The ball's angular velocity before the bounce, rad/s, in the frame's own rotation convention; finite.</param>
        /// <returns>
        /// The outgoing state. A ball that is not moving into the surface (velocity . normal &gt;= 0) comes back
        /// unchanged with <see cref="BounceRegime.None"/>.
        /// </returns>
        /// <exception cref="System.ArgumentException">An argument is null, not finite, or the normal is zero.</exception>
        BounceOutcome Bounce(Ball ball, in Vector3d normal, in Vector3d velocity, in Vector3d angularVelocity);
    }

    /// <summary>How the contact point behaved during a bounce.</summary>
    public enum BounceRegime
    {
        /// <summary>No bounce: the ball was not moving into the surface.</summary>
        None = 0,

        /// <summary>The contact point slid for the whole bounce; friction mu N acted throughout.</summary>
        Slide = 1,

        /// <summary>The contact point stopped sliding (gripped) and recoiled with the tangential COR e_x.</summary>
        Grip = 2,
    }

    /// <summary>The result of one bounce: outgoing velocity and spin, the regime, and the coefficients used.</summary>
    public readonly struct BounceOutcome
    {
        /// <summary>Velocity just after the bounce, m/s.</summary>
        public readonly Vector3d Velocity;

        /// <summary>Angular velocity just after the bounce, rad/s.</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>Whether the ball slid throughout or gripped.</summary>
        public readonly BounceRegime Regime;

        /// <summary>The normal COR e_y that was applied (0 when <see cref="Regime"/> is None).</summary>
        public readonly double NormalRestitution;

        /// <summary>The incoming speed into the surface, -v1 . n, m/s (0 when not approaching).</summary>
        public readonly double IncomingNormalSpeed;

        /// <summary>Creates an outcome.</summary>
        /// <param name="velocity">Outgoing velocity, m/s.</param>
        /// <param name="angularVelocity">Outgoing angular velocity, rad/s.</param>
        /// <param name="regime">The regime.</param>
        /// <param name="normalRestitution">The normal COR applied.</param>
        /// <param name="incomingNormalSpeed">The incoming normal speed, m/s.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public BounceOutcome(in Vector3d velocity, in Vector3d angularVelocity, BounceRegime regime, double normalRestitution, double incomingNormalSpeed)
        {
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Regime = regime;
            NormalRestitution = normalRestitution;
            IncomingNormalSpeed = incomingNormalSpeed;
        }

        /// <inheritdoc />
        public override string ToString() => $"{Regime}: v={Velocity} w={AngularVelocity} e_y={NormalRestitution:R}";
    }
}
