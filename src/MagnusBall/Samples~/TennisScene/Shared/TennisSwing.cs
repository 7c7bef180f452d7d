#nullable enable
using System;
using System.Globalization;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>
    /// A tennis shot defined by the swing that makes it, not by its launch: where the ball is met, how it arrives
    /// (the toss of a serve is at rest; a rally ball comes from the far side), and the racket swing
    /// (<see cref="RacketSwing"/>: racket speed, path, face tilt and turn, impact point through the ACOR). The launch is
    /// what the library's impact law makes of it (<see cref="Launch"/>). Immutable.
    /// </summary>
    /// <remarks>
    /// The swing's angles are measured in the court's launch frame <see cref="Frame"/>: up +y, forward +x (down the
    /// court). That frame's side is up x forward = -z, the hitter's right, so a RacketSwing azimuth or face turn is
    /// positive toward the hitter's right (the opposite of <see cref="TennisShot.AzimuthDegrees"/>).
    /// </remarks>
    public sealed class TennisSwing
    {
        /// <summary>Creates a swing shot.</summary>
        /// <param name="name">A short name for tables.</param>
        /// <param name="start">The ball's centre at impact, m (court frame).</param>
        /// <param name="incomingVelocity">The ball's velocity before the impact, m/s (zero for a serve's toss at its apex).</param>
        /// <param name="incomingTopspinRpm">The incoming ball's topspin, rpm, by effect about its velocity (negative: backspin; ignored when it is at rest).</param>
        /// <param name="swing">The racket swing.</param>
        /// <param name="target">Where the shot must land to be good.</param>
        /// <exception cref="ArgumentException">The name is empty or a number is not finite.</exception>
        public TennisSwing(string name, Vector3d start, Vector3d incomingVelocity, double incomingTopspinRpm, RacketSwing swing, TargetArea target)
        {
            if (string.IsNullOrWhiteSpace(name))
            {
                throw new ArgumentException("name must be a non-empty shot name.", nameof(name));
            }

            if (!start.IsFinite || !incomingVelocity.IsFinite || double.IsNaN(incomingTopspinRpm) || double.IsInfinity(incomingTopspinRpm))
            {
                throw new ArgumentException("start, incomingVelocity and incomingTopspinRpm must be finite.", nameof(start));
            }

            if (swing.Speed == 0)
            {
                throw new ArgumentException("swing must be built by a RacketSwing constructor.", nameof(swing));
            }

            Name = name;
            Start = start;
            IncomingVelocity = incomingVelocity;
            IncomingTopspinRpm = incomingTopspinRpm;
            Swing = swing;
            Target = target;
        }

        /// <summary>The court's launch frame: up +y, forward +x, side -z (the hitter's right).</summary>
        public static LaunchFrame Frame => new LaunchFrame(TennisCourt.Up, TennisCourt.Downrange);

        /// <summary>The shot's name.</summary>
        public string Name { get; }

        /// <summary>The ball's centre at impact, m.</summary>
        public Vector3d Start { get; }

        /// <summary>The ball's velocity before the impact, m/s.</summary>
        public Vector3d IncomingVelocity { get; }

        /// <summary>The incoming ball's topspin, rpm (negative: backspin).</summary>
        public double IncomingTopspinRpm { get; }

        /// <summary>The racket swing.</summary>
        public RacketSwing Swing { get; }

        /// <summary>Where the shot must land to be good.</summary>
        public TargetArea Target { get; }

        /// <summary>The incoming ball's angular velocity, rad/s.</summary>
        public Vector3d IncomingSpin =>
            IncomingVelocity.LengthSquared == 0 || IncomingTopspinRpm == 0 ? Vector3d.Zero : TennisShot.SpinFor(IncomingVelocity, IncomingTopspinRpm, 0);

        /// <summary>The launch this swing gives the ball.</summary>
        /// <param name="ball">The ball.</param>
        public SwingLaunch Launch(Ball ball) => Swing.Hit(ball, Frame, Start, IncomingVelocity, IncomingSpin);

        /// <summary>The launch as a <see cref="TennisShot"/> (exact velocity and angular velocity), for the scene's simulation.</summary>
        /// <param name="ball">The ball.</param>
        /// <exception cref="InvalidOperationException">The racket misses the ball (it was not approaching the face).</exception>
        public TennisShot ToShot(Ball ball)
        {
            SwingLaunch launch = Launch(ball);
            if (!launch.IsHit)
            {
                throw new InvalidOperationException($"{Name}: the racket does not meet the ball ({Swing}).");
            }

            return TennisShot.FromLaunch(Name, Start, launch.Velocity, launch.AngularVelocity, Target, this);
        }

        /// <summary>A copy with another swing (for example the one the inverse found).</summary>
        /// <param name="swing">The swing.</param>
        public TennisSwing WithSwing(RacketSwing swing) => new TennisSwing(Name, Start, IncomingVelocity, IncomingTopspinRpm, swing, Target);

        /// <summary>The swing in a few words, for tables: racket speed, path, face tilt, face turn, ACOR, azimuth.</summary>
        public string Describe() => string.Format(
            CultureInfo.InvariantCulture, "racket {0,5:F1} m/s path {1,6:F1} face {2,7:F3} turn {3,5:F1} ACOR {4:F2} azim {5,7:F3}",
            Swing.Speed, Swing.PathElevationDegrees, Swing.FaceTiltDegrees, Swing.FaceTurnDegrees, Swing.ApparentRestitution, Swing.AzimuthDegrees);
    }
}
