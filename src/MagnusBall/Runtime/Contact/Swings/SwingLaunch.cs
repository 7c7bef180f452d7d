using System;

namespace MagnusBall.Contact.Swings
{
    /// <summary>
    /// What a swing did to the ball: the impact (<see cref="ImpactOutcome"/>) described in a launch frame, as a
    /// player, a launch monitor or an aim solver describes a launch: speed, elevation, azimuth and the spin by effect.
    /// </summary>
    public readonly struct SwingLaunch
    {
        /// <summary>Creates the description of an impact in a frame.</summary>
        /// <param name="impact">The impact.</param>
        /// <param name="frame">The launch frame (up, forward, side); not the default frame.</param>
        /// <exception cref="ArgumentException">The frame is the default value (no up or forward); the message names it.</exception>
        internal SwingLaunch(in ImpactOutcome impact, in LaunchFrame frame)
        {
            SwingGeometry.RequireFrame(frame, nameof(frame));
            Impact = impact;
            Frame = frame;
        }

        /// <summary>The impact: outgoing velocity and spin, impulse, regime.</summary>
        public ImpactOutcome Impact { get; }

        /// <summary>The frame the angles and spins are measured in.</summary>
        internal LaunchFrame Frame { get; }

        /// <summary>True when the body and the ball met (the ball was approaching the face in the body's frame).</summary>
        public bool IsHit => Impact.Regime != BounceRegime.None;

        /// <summary>The launch velocity, m/s.</summary>
        public Vector3d Velocity => Impact.Velocity;

        /// <summary>The launch angular velocity, rad/s.</summary>
        public Vector3d AngularVelocity => Impact.AngularVelocity;

        /// <summary>Launch speed, m/s.</summary>
        public double Speed => Impact.Velocity.Length;

        /// <summary>Launch elevation above the frame's horizontal, rad.</summary>
        internal double ElevationRadians
        {
            get
            {
                Vector3d v = Impact.Velocity;
                double up = Vector3d.Dot(v, Frame.Up);
                Vector3d horizontal = v - Frame.Up * up;
                return PortableMath.Atan2(up, horizontal.Length);
            }
        }

        /// <summary>Launch azimuth from the frame's forward toward its side, rad.</summary>
        internal double AzimuthRadians => PortableMath.Atan2(Vector3d.Dot(Impact.Velocity, Frame.Side), Vector3d.Dot(Impact.Velocity, Frame.Forward));

        /// <summary>Launch elevation, degrees.</summary>
        public double ElevationDegrees => ElevationRadians * (180 / Math.PI);

        /// <summary>Launch azimuth, degrees (toward <see cref="LaunchFrame.Side"/>).</summary>
        public double AzimuthDegrees => AzimuthRadians * (180 / Math.PI);

        /// <summary>Spin rate, rad/s.</summary>
        internal double SpinRate => Impact.AngularVelocity.Length;

        /// <summary>Spin rate, rev/min.</summary>
        public double SpinRpm => Spin.ToRpm(SpinRate);

        /// <summary>
        /// The spin by effect relative to the launch direction, in the aim solvers' convention
        /// (<see cref="LaunchSpin"/>: topspin dips, negative is backspin; sidespin curves toward the frame's side;
        /// gyro about the direction of flight). Resolving it at this launch's direction gives <see cref="AngularVelocity"/> back.
        /// </summary>
        public LaunchSpin LaunchSpin
        {
            get
            {
                Vector3d v = Impact.Velocity;
                if (v.LengthSquared == 0)
                {
                    return LaunchSpin.None;
                }

                Vector3d w = Impact.AngularVelocity;
                Vector3d top = new LaunchSpin(1).AngularVelocity(v, Frame);
                Vector3d side = new LaunchSpin(0, 1).AngularVelocity(v, Frame);
                Vector3d gyro = new LaunchSpin(0, 0, 1).AngularVelocity(v, Frame);
                return new LaunchSpin(Vector3d.Dot(w, top), Vector3d.Dot(w, side), Vector3d.Dot(w, gyro));
            }
        }

        /// <summary>
        /// The spin axis's tilt, degrees, as golf launch monitors give it: atan2(sidespin, backspin), 0 for pure backspin,
        /// positive when the ball curves toward the frame's side.
        /// </summary>
        public double SpinAxisDegrees
        {
            get
            {
                LaunchSpin s = LaunchSpin;
                return PortableMath.Atan2(s.Sidespin, -s.Topspin) * (180 / Math.PI);
            }
        }

        /// <summary>The launch state at <paramref name="position"/>.</summary>
        /// <param name="position">The ball's centre, m.</param>
        /// <param name="time">The time, s.</param>
        public FlightState LaunchState(in Vector3d position, double time = 0) => Impact.LaunchState(position, time);

        /// <inheritdoc />
        public override string ToString() =>
            FormattableString.Invariant($"SwingLaunch({Speed:F2} m/s, elevation {ElevationDegrees:F2} deg, azimuth {AzimuthDegrees:F2} deg, {SpinRpm:F0} rpm, {Impact.Regime})");
    }

    /// <summary>Shared checks and geometry of the swing helpers.</summary>
    internal static class SwingGeometry
    {
        internal const double Degree = Math.PI / 180;

        internal static void RequireFrame(in LaunchFrame frame, string name)
        {
            if (frame.Up.LengthSquared == 0)
            {
                throw new ArgumentException($"{name} must be a LaunchFrame built from an up and a forward direction; got the default (zero) frame.", name);
            }
        }

        /// <summary>Refuses a swing that is the default value of its struct (speed 0: built by no constructor).</summary>
        internal static void RequireBuilt(double speed, string type)
        {
            if (speed == 0)
            {
                throw new InvalidOperationException($"this {type} is the default value (speed 0); build it with a {type} constructor.");
            }
        }

        /// <summary>The smallest mass of a struck body (a foot, a club head) the swing helpers accept, kg: a milligram.</summary>
        internal const double MinimumBodyMass = 1e-6;

        /// <summary>A body mass: finite and &gt;= <see cref="MinimumBodyMass"/> (lighter ones overflow the law's mass ratio).</summary>
        internal static double RequireBodyMass(double value, string name)
        {
            if (double.IsFinite(value) && value >= MinimumBodyMass)
            {
                return value;
            }

            throw new ArgumentOutOfRangeException(
                name, value, $"{name} must be finite and >= {Require.Format(MinimumBodyMass)} kg; got {Require.Format(value)}.");
        }

        /// <summary>Refuses a ball over 1e12 times the struck body's mass (the impact law's limit), naming the ball.</summary>
        internal static void RequireMassRatio(Ball ball, double bodyMass, string bodyName)
        {
            if (!(ball.Mass / bodyMass <= Impact.MaximumMassRatio))
            {
                throw new ArgumentException(
                    $"ball's mass {Require.Format(ball.Mass)} kg must be at most {Require.Format(Impact.MaximumMassRatio)} times the {bodyName}'s "
                    + $"{Require.Format(bodyMass)} kg (the impact law's limit).", "ball");
            }
        }

        /// <summary>The unit vector across <paramref name="direction"/> in the plane of it and up (up's part across it).</summary>
        internal static Vector3d UpAcross(in LaunchFrame frame, in Vector3d direction)
        {
            Vector3d u = frame.Up - direction * Vector3d.Dot(frame.Up, direction);
            return u.LengthSquared > 1e-24 ? u.NormalizedOrZero() : -frame.Forward;
        }

        /// <summary>The unit vector across <paramref name="direction"/> and up, toward the frame's side.</summary>
        internal static Vector3d SideAcross(in LaunchFrame frame, in Vector3d direction) =>
            Vector3d.Cross(frame.Up, direction).NormalizedOrZero() is Vector3d s && s.LengthSquared > 0 ? s : frame.Side;
    }
}
