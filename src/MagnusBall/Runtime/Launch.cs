using System;

namespace MagnusBall
{
    /// <summary>
    /// The directions a launch is described in: up, a horizontal forward direction and a horizontal side
    /// direction. Elevation turns the launch from the horizontal toward up; azimuth turns it about up
    /// from forward toward side.
    /// </summary>
    /// <remarks>
    /// <see cref="Side"/> is normalize(up x forward). The cross product is the same formula in every frame,
    /// so which physical side that is depends on the frame's handedness: in a right-handed frame it is the
    /// left of forward (z-up, x forward: side = +y), in Unity's left-handed y-up frame it is the right.
    /// Where it matters, work with the returned world vectors (<see cref="Direction"/>,
    /// the aim solver's <c>AimSolution.Velocity</c>), which mean the same thing in every frame.
    /// </remarks>
    public readonly struct LaunchFrame
    {
        /// <summary>Unit up direction.</summary>
        public readonly Vector3d Up;

        /// <summary>Unit horizontal forward direction (perpendicular to <see cref="Up"/>).</summary>
        public readonly Vector3d Forward;

        /// <summary>Unit horizontal side direction, normalize(Up x Forward).</summary>
        public readonly Vector3d Side;

        /// <summary>Creates a frame from an up direction and a forward direction (its part across up is used).</summary>
        /// <param name="up">Up (for example <see cref="FlightModel.Up"/>); finite, non-zero.</param>
        /// <param name="forward">Forward; finite, not parallel to up.</param>
        /// <exception cref="ArgumentException">A vector is zero or not finite, or forward is parallel to up.</exception>
        public LaunchFrame(Vector3d up, Vector3d forward)
        {
            Require.NonZero(up, nameof(up));
            Require.NonZero(forward, nameof(forward));
            Vector3d u = up.NormalizedOrZero();
            Vector3d f = forward - u * Vector3d.Dot(forward, u);
            if (!(f.Length > 1e-9 * forward.Length))
            {
                throw new ArgumentException($"forward must not be parallel to up; got forward {forward}, up {up}.", nameof(forward));
            }

            Up = u;
            Forward = f.NormalizedOrZero();
            Side = Vector3d.Cross(Up, Forward).NormalizedOrZero();
        }

        /// <summary>The unit launch direction cos(e) (cos(a) forward + sin(a) side) + sin(e) up.</summary>
        /// <param name="elevationRadians">Elevation above the horizontal, rad; finite.</param>
        /// <param name="azimuthRadians">Azimuth from forward toward side, rad; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">An angle is NaN or infinite (the message names it).</exception>
        public Vector3d Direction(double elevationRadians, double azimuthRadians)
        {
            Require.Finite(elevationRadians, nameof(elevationRadians));
            Require.Finite(azimuthRadians, nameof(azimuthRadians));
            double ce = PortableMath.Cos(elevationRadians);
            return Forward * (ce * PortableMath.Cos(azimuthRadians)) + Side * (ce * PortableMath.Sin(azimuthRadians)) + Up * PortableMath.Sin(elevationRadians);
        }
    }

    /// <summary>
    /// A spin described by its effect relative to the launch direction, so that it turns with the aim:
    /// topspin (negative: backspin), sidespin toward the frame's side, and gyro spin along the flight.
    /// Resolve it to an angular velocity with <see cref="AngularVelocity"/>.
    /// </summary>
    /// <remarks>
    /// <para>For launch direction f, the "lift" direction u' is the part of up across f, and the side
    /// direction s' is the part of <see cref="LaunchFrame.Side"/> across both. Then</para>
    /// <code>w = Topspin (f x -u') + Sidespin (f x s') + Gyro f</code>
    /// <para>Since (f x d) x f = d for unit perpendicular f and d in any handedness, topspin curves the ball
    /// toward -up (it dips), backspin toward up, positive sidespin toward the side direction: the same
    /// effect in z-up, y-up, left- and right-handed frames (see <see cref="Spin.Toward"/>). Every part is
    /// perpendicular to the launch velocity except the gyro part, which the transverse-spin Magnus force
    /// ignores.</para>
    /// <para>A launch in the plane of up and side (azimuth exactly +-90 degrees, within 1e-12 rad) has no part
    /// of Side across f and u'. Sidespin then uses s' = -forward for a launch toward +side and +forward toward
    /// -side: the limit as the azimuth approaches +-90 degrees from the forward half (|azimuth| &lt; 90 degrees),
    /// so it neither vanishes nor jumps for aims that turn toward the side.</para>
    /// </remarks>
    public readonly struct LaunchSpin
    {
        /// <summary>Topspin rate, rad/s (negative: backspin).</summary>
        public readonly double Topspin;

        /// <summary>Sidespin rate, rad/s: positive curves toward <see cref="LaunchFrame.Side"/>, negative away from it.</summary>
        public readonly double Sidespin;

        /// <summary>Gyro (rifle) spin about the launch direction, rad/s.</summary>
        public readonly double Gyro;

        /// <summary>Creates a spin by effect.</summary>
        /// <param name="topspin">Topspin rate, rad/s (negative: backspin); finite.</param>
        /// <param name="sidespin">Sidespin rate toward the frame's side, rad/s; finite.</param>
        /// <param name="gyro">Spin about the launch direction, rad/s; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">A rate is not finite.</exception>
        public LaunchSpin(double topspin, double sidespin = 0, double gyro = 0)
        {
            Topspin = Require.Finite(topspin, nameof(topspin));
            Sidespin = Require.Finite(sidespin, nameof(sidespin));
            Gyro = Require.Finite(gyro, nameof(gyro));
        }

        /// <summary>No spin.</summary>
        public static LaunchSpin None => default;

        /// <summary>Pure backspin of <paramref name="rate"/> rad/s (the ball floats).</summary>
        /// <param name="rate">Rate, rad/s; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="rate"/> is not finite.</exception>
        public static LaunchSpin Backspin(double rate) => new LaunchSpin(-Require.Finite(rate, nameof(rate)));

        /// <summary>
        /// The angular velocity this spin has for a ball launched along <paramref name="direction"/> in
        /// <paramref name="frame"/>.
        /// </summary>
        /// <param name="direction">The launch direction (need not be unit); finite, non-zero.</param>
        /// <param name="frame">The launch frame (for up and side).</param>
        /// <returns>The angular velocity, rad/s. For a vertical launch, "across up" falls back to -forward.</returns>
        /// <exception cref="ArgumentException">direction is zero or not finite, or frame is the default (zero) frame.</exception>
        public Vector3d AngularVelocity(in Vector3d direction, in LaunchFrame frame)
        {
            Require.NonZero(direction, nameof(direction));
            if (frame.Up.LengthSquared == 0)
            {
                throw new ArgumentException("frame must be a LaunchFrame built from an up and a forward direction; got the default (zero) frame.", nameof(frame));
            }

            Vector3d f = direction.NormalizedOrZero();
            Vector3d lift = frame.Up - f * Vector3d.Dot(frame.Up, f);
            if (lift.LengthSquared < 1e-24)
            {
                lift = -frame.Forward;
            }

            lift = lift.NormalizedOrZero();
            Vector3d side = frame.Side - f * Vector3d.Dot(frame.Side, f);
            side -= lift * Vector3d.Dot(side, lift);
            if (side.LengthSquared < 1e-24)
            {
                // Launched in the plane of up and side (azimuth +-90 degrees): no part of Side lies across both f
                // and u'. Use the limit from launches with a forward part (|azimuth| < 90 degrees).
                side = frame.Forward * -Math.Sign(Vector3d.Dot(frame.Side, f));
            }

            side = side.NormalizedOrZero();
            return Vector3d.Cross(f, -lift) * Topspin + Vector3d.Cross(f, side) * Sidespin + f * Gyro;
        }

        /// <inheritdoc />
        public override string ToString() => $"LaunchSpin(topspin={Topspin:R}, sidespin={Sidespin:R}, gyro={Gyro:R} rad/s)";
    }
}
