#nullable enable
using System;

namespace MagnusBall.Samples.TennisScene
{
    /// <summary>
    /// A tennis shot as a player would describe it: where it is hit from, how fast, at what elevation and
    /// azimuth, with how much topspin (negative: backspin) and sidespin, and where it must land. Immutable.
    /// </summary>
    /// <remarks>
    /// Spin is built by its effect, not from axis components: topspin makes the ball dip, sidespin curls it
    /// toward the hitter's left (+z) when positive. <see cref="MagnusBall.Spin.Toward"/> turns that into the
    /// angular velocity w = rate normalize(v x d), which is right in Unity's left-handed frame and in any
    /// right-handed one alike (the triple product (v x d) x v = d uses no handedness), so the sample never
    /// flips a sign by hand.
    /// </remarks>
    public sealed class TennisShot
    {
        /// <summary>Creates a shot.</summary>
        /// <param name="name">A short name for tables and legends.</param>
        /// <param name="start">Where the ball's centre is when hit, m (court frame, see <see cref="TennisCourt"/>).</param>
        /// <param name="speed">Launch speed, m/s; finite and &gt; 0.</param>
        /// <param name="elevationDegrees">Launch angle above the horizontal, deg, in (-90, 90).</param>
        /// <param name="azimuthDegrees">Launch direction from +x toward the hitter's left (+z), deg.</param>
        /// <param name="topspinRpm">Topspin, rev/min; negative for backspin (slice).</param>
        /// <param name="sidespinRpm">Sidespin, rev/min; positive curls the ball to the hitter's left (+z).</param>
        /// <param name="target">Where the shot must land to be good.</param>
        /// <exception cref="ArgumentException">A number is out of range or not finite.</exception>
        public TennisShot(
            string name, Vector3d start, double speed, double elevationDegrees, double azimuthDegrees,
            double topspinRpm, double sidespinRpm, TargetArea target)
        {
            if (string.IsNullOrWhiteSpace(name))
            {
                throw new ArgumentException("name must be a non-empty shot name.", nameof(name));
            }

            RequireFinite(start.X, "start"); RequireFinite(start.Y, "start"); RequireFinite(start.Z, "start");
            if (!(speed > 0) || double.IsInfinity(speed))
            {
                throw new ArgumentOutOfRangeException(nameof(speed), speed, $"speed must be finite and > 0 m/s; got {speed}.");
            }

            if (!(elevationDegrees > -90 && elevationDegrees < 90))
            {
                throw new ArgumentOutOfRangeException(nameof(elevationDegrees), elevationDegrees, $"elevation must be in (-90, 90) deg; got {elevationDegrees}.");
            }

            RequireFinite(azimuthDegrees, "azimuth");
            RequireFinite(topspinRpm, "topspin");
            RequireFinite(sidespinRpm, "sidespin");
            Name = name;
            Start = start;
            Speed = speed;
            ElevationDegrees = elevationDegrees;
            AzimuthDegrees = azimuthDegrees;
            TopspinRpm = topspinRpm;
            SidespinRpm = sidespinRpm;
            Target = target;
        }

        private TennisShot(string name, Vector3d start, Vector3d velocity, Vector3d angularVelocity, TargetArea target, TennisSwing? swing)
            : this(
                name, start, velocity.Length, ElevationOf(velocity), AzimuthOf(velocity),
                Spin.ToRpm(Vector3d.Dot(angularVelocity, TopspinAxis(velocity))), Spin.ToRpm(Vector3d.Dot(angularVelocity, SidespinAxis(velocity))), target)
        {
            _velocity = velocity;
            _angularVelocity = angularVelocity;
            Swing = swing;
        }

        private readonly Vector3d? _velocity;
        private readonly Vector3d? _angularVelocity;

        /// <summary>
        /// A shot launched with exactly this velocity and angular velocity (for example the launch a racket swing produced,
        /// see <see cref="TennisSwing"/>). Speed, angles and the topspin and sidespin components are derived for the table;
        /// the angular velocity is kept as given (including any part about the direction of flight).
        /// </summary>
        /// <param name="name">The shot's name.</param>
        /// <param name="start">Where the ball's centre is when hit, m.</param>
        /// <param name="velocity">Launch velocity, m/s; finite, not zero, not vertical.</param>
        /// <param name="angularVelocity">Launch angular velocity, rad/s; finite.</param>
        /// <param name="target">Where the shot must land to be good.</param>
        /// <param name="swing">The swing that produced the launch, or null.</param>
        /// <exception cref="ArgumentException">A value is out of range or not finite.</exception>
        public static TennisShot FromLaunch(string name, Vector3d start, Vector3d velocity, Vector3d angularVelocity, TargetArea target, TennisSwing? swing = null)
        {
            RequireFinite(angularVelocity.X, "angularVelocity"); RequireFinite(angularVelocity.Y, "angularVelocity"); RequireFinite(angularVelocity.Z, "angularVelocity");
            return new TennisShot(name, start, velocity, angularVelocity, target, swing);
        }

        /// <summary>The racket swing this shot was made by, or null for a shot defined by its launch.</summary>
        public TennisSwing? Swing { get; }

        /// <summary>The shot's name.</summary>
        public string Name { get; }

        /// <summary>Where the ball's centre is when hit, m.</summary>
        public Vector3d Start { get; }

        /// <summary>Launch speed, m/s.</summary>
        public double Speed { get; }

        /// <summary>Launch angle above the horizontal, deg.</summary>
        public double ElevationDegrees { get; }

        /// <summary>Launch direction from +x toward +z (the hitter's left), deg.</summary>
        public double AzimuthDegrees { get; }

        /// <summary>Topspin, rev/min (negative: backspin).</summary>
        public double TopspinRpm { get; }

        /// <summary>Sidespin, rev/min (positive curls to the hitter's left).</summary>
        public double SidespinRpm { get; }

        /// <summary>Where the shot must land to be good.</summary>
        public TargetArea Target { get; }

        /// <summary>The launch velocity, m/s, in the court frame.</summary>
        public Vector3d Velocity
        {
            get
            {
                if (_velocity.HasValue)
                {
                    return _velocity.Value;
                }

                double e = ElevationDegrees * Math.PI / 180, a = AzimuthDegrees * Math.PI / 180;
                return TennisCourt.Downrange * (Speed * Math.Cos(e) * Math.Cos(a))
                    + TennisCourt.Left * (Speed * Math.Cos(e) * Math.Sin(a))
                    + TennisCourt.Up * (Speed * Math.Sin(e));
            }
        }

        /// <summary>The launch angular velocity, rad/s, built by effect (see the class remarks).</summary>
        public Vector3d AngularVelocity => _angularVelocity ?? SpinFor(Velocity, TopspinRpm, SidespinRpm);

        /// <summary>The launch state at time 0.</summary>
        public FlightState Launch() => new FlightState(Start, Velocity, AngularVelocity);

        /// <summary>A copy with other launch angles (used when aiming).</summary>
        /// <param name="elevationDegrees">Elevation, deg.</param>
        /// <param name="azimuthDegrees">Azimuth, deg.</param>
        public TennisShot WithAngles(double elevationDegrees, double azimuthDegrees) =>
            new TennisShot(Name, Start, Speed, elevationDegrees, azimuthDegrees, TopspinRpm, SidespinRpm, Target);

        /// <summary>
        /// The angular velocity, rad/s, of <paramref name="topspinRpm"/> topspin (negative: backspin) and
        /// <paramref name="sidespinRpm"/> sidespin curling toward the hitter's left, for a ball moving along
        /// <paramref name="velocity"/> in the court frame.
        /// </summary>
        /// <param name="velocity">Launch velocity, m/s (not vertical when there is spin).</param>
        /// <param name="topspinRpm">Topspin, rev/min; negative for backspin.</param>
        /// <param name="sidespinRpm">Sidespin, rev/min; positive curls toward +z.</param>
        public static Vector3d SpinFor(Vector3d velocity, double topspinRpm, double sidespinRpm)
        {
            Vector3d spin = Vector3d.Zero;
            if (topspinRpm > 0)
            {
                spin += Spin.Topspin(velocity, TennisCourt.Up, Spin.FromRpm(topspinRpm));
            }
            else if (topspinRpm < 0)
            {
                spin += Spin.Backspin(velocity, TennisCourt.Up, Spin.FromRpm(-topspinRpm));
            }

            if (sidespinRpm > 0)
            {
                spin += Spin.Toward(velocity, TennisCourt.Left, Spin.FromRpm(sidespinRpm));
            }
            else if (sidespinRpm < 0)
            {
                spin += Spin.Toward(velocity, -TennisCourt.Left, Spin.FromRpm(-sidespinRpm));
            }

            return spin;
        }

        private static double ElevationOf(Vector3d v) =>
            Math.Atan2(Vector3d.Dot(v, TennisCourt.Up), Math.Sqrt(Math.Pow(Vector3d.Dot(v, TennisCourt.Downrange), 2) + Math.Pow(Vector3d.Dot(v, TennisCourt.Left), 2))) * (180 / Math.PI);

        private static double AzimuthOf(Vector3d v) =>
            Math.Atan2(Vector3d.Dot(v, TennisCourt.Left), Vector3d.Dot(v, TennisCourt.Downrange)) * (180 / Math.PI);

        // The axes SpinFor uses: topspin normalize(v x -up), sidespin toward Left normalize(v x left-across-v).
        private static Vector3d TopspinAxis(Vector3d v) => Vector3d.Cross(v, -TennisCourt.Up).NormalizedOrZero();

        private static Vector3d SidespinAxis(Vector3d v)
        {
            Vector3d u = v.NormalizedOrZero();
            Vector3d across = TennisCourt.Left - u * Vector3d.Dot(TennisCourt.Left, u);
            return Vector3d.Cross(u, across.NormalizedOrZero()).NormalizedOrZero();
        }

        private static void RequireFinite(double value, string name)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
            {
                throw new ArgumentOutOfRangeException(name, value, $"{name} must be a finite number; got {value}.");
            }
        }
    }
}
