using System;
using System.Globalization;

namespace MagnusBall.Shots
{
    /// <summary>
    /// A launch in game terms: speed, elevation and direction in degrees from the frame's forward axis, and spin by its
    /// effect in rpm. Build it from the terms your sport uses (<see cref="ByEffect"/>, TrackMan's
    /// <see cref="TrackMan"/>, Statcast's <see cref="Statcast(Speed, double, double, double, double, double)"/>); fly it
    /// with <see cref="ShotFlyer"/>, which puts it into a frame (z-up, Unity's y-up, any other).
    /// </summary>
    /// <remarks>
    /// Signs: elevation positive above the horizontal; direction positive to the frame's right; topspin positive makes
    /// the ball dip (negative: backspin, it floats); sidespin positive curves it to the right; gyro spin is about the
    /// flight direction and curves nothing (it is the part a spin efficiency below 1 leaves).
    /// </remarks>
    public readonly struct ShotLaunch
    {
        private ShotLaunch(double speed, double elevation, double direction, double top, double side, double gyro)
        {
            SpeedMetresPerSecond = speed;
            ElevationDegrees = elevation;
            DirectionDegrees = direction;
            TopspinRpm = top;
            SidespinRpm = side;
            GyroRpm = gyro;
        }

        /// <summary>Launch speed, m/s.</summary>
        public double SpeedMetresPerSecond { get; }

        /// <summary>Elevation above the horizontal, degrees.</summary>
        public double ElevationDegrees { get; }

        /// <summary>Direction from the frame's forward axis, degrees, positive to the right.</summary>
        public double DirectionDegrees { get; }

        /// <summary>Topspin, rpm: positive dips, negative (backspin) floats.</summary>
        public double TopspinRpm { get; }

        /// <summary>Sidespin, rpm: positive curves the ball to the right, negative to the left.</summary>
        public double SidespinRpm { get; }

        /// <summary>
        /// Gyro (rifle) spin about the flight direction, rpm: positive turns clockwise seen from behind the ball (a right-handed
        /// screw along the flight). It curves nothing at the launch.
        /// </summary>
        public double GyroRpm { get; }

        /// <summary>A launch with spin given by its effect.</summary>
        /// <param name="speed">Launch speed (<see cref="Speed.FromKilometresPerHour"/>, ...).</param>
        /// <param name="elevationDegrees">Elevation above the horizontal, degrees; in [-90, 90].</param>
        /// <param name="directionDegrees">Direction from forward, degrees, positive right; in [-180, 180].</param>
        /// <param name="topspinRpm">Topspin, rpm (negative: backspin); finite.</param>
        /// <param name="sidespinRpm">Sidespin, rpm, positive curving right; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">An angle is outside its range or a rate is not finite (the message names it).</exception>
        public static ShotLaunch ByEffect(Speed speed, double elevationDegrees, double directionDegrees = 0, double topspinRpm = 0, double sidespinRpm = 0)
        {
            CheckAngles(elevationDegrees, directionDegrees, nameof(elevationDegrees), nameof(directionDegrees));
            Require.Finite(topspinRpm, nameof(topspinRpm));
            Require.Finite(sidespinRpm, nameof(sidespinRpm));
            return new ShotLaunch(speed.MetresPerSecond, elevationDegrees, directionDegrees, topspinRpm, sidespinRpm, 0);
        }

        /// <summary>
        /// A launch as TrackMan reports a golf shot: ball speed, launch angle, launch direction, spin rate and spin axis.
        /// The spin axis is the tilt of the backspin axis, degrees, positive to the right (the ball curves right: a fade
        /// or slice for a right-hander); backspin = rate cos(axis), sidespin = rate sin(axis), no gyro spin.
        /// </summary>
        /// <param name="ballSpeed">Ball speed (TrackMan publishes mph: <see cref="Speed.FromMilesPerHour"/>).</param>
        /// <param name="launchAngleDegrees">Launch angle, degrees; in [-90, 90].</param>
        /// <param name="launchDirectionDegrees">Launch direction from forward (the target line), degrees, positive right; in [-180, 180].</param>
        /// <param name="spinRateRpm">Spin rate, rpm; finite and &gt;= 0.</param>
        /// <param name="spinAxisDegrees">Spin axis, degrees, positive tilted right; in [-90, 90].</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is outside its range (the message names it).</exception>
        public static ShotLaunch TrackMan(Speed ballSpeed, double launchAngleDegrees, double launchDirectionDegrees, double spinRateRpm, double spinAxisDegrees = 0)
        {
            CheckAngles(launchAngleDegrees, launchDirectionDegrees, nameof(launchAngleDegrees), nameof(launchDirectionDegrees));
            Require.NonNegative(spinRateRpm, nameof(spinRateRpm));
            Require.InRange(spinAxisDegrees, -90, 90, nameof(spinAxisDegrees));
            double axis = spinAxisDegrees * (Math.PI / 180);
            return new ShotLaunch(ballSpeed.MetresPerSecond, launchAngleDegrees, launchDirectionDegrees,
                -spinRateRpm * PortableMath.Cos(axis), spinRateRpm * PortableMath.Sin(axis), 0);
        }

        /// <summary>
        /// A pitch as Statcast reports it: release speed, spin rate, spin axis in degrees (0 to 360: 180 is pure backspin,
        /// 0 pure topspin, the 12-6 curveball; a right-hander's four-seamer sits near 210-225, moving up and to his arm
        /// side, the third-base side) and an optional spin efficiency (the share of the spin that moves the ball; the
        /// rest is gyro spin). The frame's forward is toward home plate, so its right is the pitcher's right.
        /// </summary>
        /// <param name="releaseSpeed">Release speed (Statcast publishes mph: <see cref="Speed.FromMilesPerHour"/>).</param>
        /// <param name="elevationDegrees">Release angle above the horizontal, degrees; in [-90, 90].</param>
        /// <param name="directionDegrees">Release direction from forward, degrees, positive to the pitcher's right; in [-180, 180].</param>
        /// <param name="spinRateRpm">Spin rate, rpm; finite and &gt;= 0.</param>
        /// <param name="spinAxisDegrees">Statcast's spin axis, degrees; finite (taken modulo 360).</param>
        /// <param name="spinEfficiency">Share of the spin across the flight, in [0, 1]; 1 when not known.</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is outside its range (the message names it).</exception>
        public static ShotLaunch Statcast(
            Speed releaseSpeed, double elevationDegrees, double directionDegrees, double spinRateRpm, double spinAxisDegrees, double spinEfficiency = 1)
        {
            CheckAngles(elevationDegrees, directionDegrees, nameof(elevationDegrees), nameof(directionDegrees));
            Require.NonNegative(spinRateRpm, nameof(spinRateRpm));
            Require.Finite(spinAxisDegrees, nameof(spinAxisDegrees));
            Require.InRange(spinEfficiency, 0, 1, nameof(spinEfficiency));
            // Statcast's spin vector lies at spinAxisDegrees in its x-z plane (x toward the catcher's right, z up), so
            // for a pitch toward the catcher the Magnus force points along sin(a) x - cos(a) z: up at 180, down at 0, toward
            // the catcher's left (the pitcher's right, this frame's right) at 270, the third-base side.
            double a = (spinAxisDegrees % 360) * (Math.PI / 180);
            double transverse = spinRateRpm * spinEfficiency;
            double gyro = spinRateRpm * Math.Sqrt(Math.Max(0, 1 - spinEfficiency * spinEfficiency));
            return new ShotLaunch(releaseSpeed.MetresPerSecond, elevationDegrees, directionDegrees,
                transverse * PortableMath.Cos(a), -transverse * PortableMath.Sin(a), gyro);
        }

        /// <summary>
        /// A pitch with Statcast's spin axis as a clock face ("tilt", as seen from the pitcher: "12:00" is pure backspin, "6:00"
        /// pure topspin, "1:30" up and to the pitcher's right); otherwise as <see cref="Statcast(Speed, double, double, double, double, double)"/>.
        /// The clock's hour h and minutes m are Statcast's axis (180 + 30 h + m / 2) modulo 360 degrees.
        /// </summary>
        /// <param name="releaseSpeed">Release speed.</param>
        /// <param name="elevationDegrees">Release angle above the horizontal, degrees; in [-90, 90].</param>
        /// <param name="directionDegrees">Release direction from forward, degrees, positive to the pitcher's right; in [-180, 180].</param>
        /// <param name="spinRateRpm">Spin rate, rpm; finite and &gt;= 0.</param>
        /// <param name="spinAxisClock">"h:mm", h from 1 to 12, mm from 00 to 59 (for example "1:30").</param>
        /// <param name="spinEfficiency">Share of the spin across the flight, in [0, 1].</param>
        /// <exception cref="ArgumentException">The clock is not "h:mm" with h 1-12 and mm 00-59, or another value is out of range.</exception>
        public static ShotLaunch Statcast(
            Speed releaseSpeed, double elevationDegrees, double directionDegrees, double spinRateRpm, string spinAxisClock, double spinEfficiency = 1) =>
            Statcast(releaseSpeed, elevationDegrees, directionDegrees, spinRateRpm, ClockDegrees(spinAxisClock), spinEfficiency);

        internal static double ClockDegrees(string clock)
        {
            string[] parts = (clock ?? string.Empty).Trim().Split(':');
            if (parts.Length == 2 && parts[1].Length == 2
                && int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out int hours) && hours >= 1 && hours <= 12
                && int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out int minutes) && minutes <= 59)
            {
                return (180 + 30 * (hours % 12) + minutes * 0.5) % 360;
            }

            throw new ArgumentException(
                $"spinAxisClock must be a clock face \"h:mm\" with h from 1 to 12 and mm from 00 to 59 (for example \"1:30\"); got '{clock ?? "null"}'.",
                "spinAxisClock");
        }

        private static void CheckAngles(double elevation, double direction, string elevationName, string directionName)
        {
            Require.InRange(elevation, -90, 90, elevationName);
            Require.InRange(direction, -180, 180, directionName);
        }

        /// <summary>The launch state at <paramref name="position"/> in <paramref name="frame"/>.</summary>
        internal FlightState ToState(in ShotFrame frame, in Vector3d position, double time)
        {
            double e = ElevationDegrees * (Math.PI / 180), a = DirectionDegrees * (Math.PI / 180);
            double ce = PortableMath.Cos(e);
            Vector3d direction = frame.Forward * (ce * PortableMath.Cos(a)) + frame.Right * (ce * PortableMath.Sin(a)) + frame.Up * PortableMath.Sin(e);
            var launchFrame = new LaunchFrame(frame.Up, frame.Forward);
            // LaunchSpin's sidespin curves toward LaunchFrame.Side = normalize(up x forward), which is right or left by handedness.
            // The gyro part is an axial vector along the flight: the same turn is +f in a right-handed frame (right = forward x up,
            // that is up x forward is left) and -f in a left-handed one, so it takes the opposite sign to the side's.
            double sideSign = Vector3d.Dot(launchFrame.Side, frame.Right) > 0 ? 1 : -1;
            var spin = new LaunchSpin(
                MagnusBall.Spin.FromRpm(TopspinRpm), sideSign * MagnusBall.Spin.FromRpm(SidespinRpm), -sideSign * MagnusBall.Spin.FromRpm(GyroRpm));
            return new FlightState(position, direction * SpeedMetresPerSecond, spin.AngularVelocity(direction, launchFrame), time);
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"ShotLaunch({SpeedMetresPerSecond:0.###} m/s, elevation {ElevationDegrees:0.###} deg, direction {DirectionDegrees:0.###} deg, " +
            $"topspin {TopspinRpm:0.#} rpm, sidespin {SidespinRpm:0.#} rpm, gyro {GyroRpm:0.#} rpm)";
    }
}
