using System;

namespace MagnusBall.Shots
{
    /// <summary>
    /// A flight in the terms a launch monitor reports (TrackMan's carry, height, landing angle, side and curve), in metres and
    /// in yards or feet, measured in the <see cref="ShotFrame"/> it was flown in. <see cref="ShotFlyer.Fly"/> makes it; the
    /// sports' judges (<see cref="TennisCourt.Judge"/>, <see cref="TableTennisTable.Judge"/>, <see cref="SoccerGoal.Judge"/>)
    /// read it.
    /// </summary>
    /// <remarks>
    /// The ball lands when it first touches the ground, the plane of the frame's origin: its centre comes down to one radius
    /// above that plane. Distances are from the launch point. When the flight does not land within its time limit,
    /// <see cref="Landed"/> is false and the landing values describe the last state.
    /// </remarks>
    public sealed class FlightSummary
    {
        private const double MetresPerYard = 0.9144, MetresPerFoot = 0.3048;
        private readonly double[] _times;
        private readonly Vector3d[] _positions, _velocities; // frame coordinates (forward, right, up)

        internal FlightSummary(double[] times, Vector3d[] positions, Vector3d[] velocities, bool landed, double apexUp, double radius)
        {
            _times = times;
            _positions = positions;
            _velocities = velocities;
            Landed = landed;
            BallRadiusMetres = radius;
            int last = positions.Length - 1;
            Vector3d start = positions[0], end = positions[last], v0 = velocities[0], v = velocities[last];
            double df = end.X - start.X, dr = end.Y - start.Y;
            CarryMetres = Math.Sqrt(df * df + dr * dr);
            SideMetres = dr;
            double a = PortableMath.Atan2(v0.Y, v0.X);
            CurveMetres = v0.X == 0 && v0.Y == 0 ? dr : dr * PortableMath.Cos(a) - df * PortableMath.Sin(a);
            ApexMetres = Math.Max(apexUp, Math.Max(start.Z, end.Z));
            FlightTimeSeconds = times[last] - times[0];
            LandingSpeedMetresPerSecond = v.Length;
            LandingAngleDegrees = PortableMath.Atan2(-v.Z, Math.Sqrt(v.X * v.X + v.Y * v.Y)) * (180 / Math.PI);
        }

        /// <summary>True when the ball came down to the ground; false when the time limit ended the flight first.</summary>
        public bool Landed { get; }

        /// <summary>Carry: the horizontal distance from the launch to the landing, m.</summary>
        public double CarryMetres { get; }

        /// <summary>Carry in yards (0.9144 m).</summary>
        public double CarryYards => CarryMetres / MetresPerYard;

        /// <summary>Apex: the highest height of the ball's centre above the ground, m.</summary>
        public double ApexMetres { get; }

        /// <summary>Apex in feet (0.3048 m).</summary>
        public double ApexFeet => ApexMetres / MetresPerFoot;

        /// <summary>Flight time from the launch to the landing, s.</summary>
        public double FlightTimeSeconds { get; }

        /// <summary>Landing angle below the horizontal, degrees (TrackMan's land angle).</summary>
        public double LandingAngleDegrees { get; }

        /// <summary>Speed at the landing, m/s.</summary>
        public double LandingSpeedMetresPerSecond { get; }

        /// <summary>Side: how far right of the forward line through the launch point the ball lands, m (negative: left).</summary>
        public double SideMetres { get; }

        /// <summary>Side in yards.</summary>
        public double SideYards => SideMetres / MetresPerYard;

        /// <summary>
        /// Curve: how far right of the launch direction's line the ball lands (the distance from that line), m; negative: it
        /// curved left. Zero for a flight that does not curve.
        /// </summary>
        public double CurveMetres { get; }

        /// <summary>Curve in yards.</summary>
        public double CurveYards => CurveMetres / MetresPerYard;

        internal double BallRadiusMetres { get; }

        /// <summary>Where the flight ended, in frame coordinates (forward, right, up).</summary>
        internal Vector3d End => _positions[_positions.Length - 1];

        /// <summary>
        /// Where the ball's centre passes <paramref name="forwardMetres"/> along forward (a net, a wall, a goal line), the first
        /// time it does before it lands, on the flight's cubic interpolant (errors far below a millimetre).
        /// </summary>
        /// <param name="forwardMetres">Distance along forward from the frame's origin, m; finite.</param>
        /// <param name="upMetres">The height of the ball's centre above the ground there, m (0 when it does not get there).</param>
        /// <param name="rightMetres">How far right of the frame's forward axis, m (0 when it does not get there).</param>
        /// <returns>True when the ball gets there before it lands.</returns>
        /// <exception cref="ArgumentOutOfRangeException">forwardMetres is not finite.</exception>
        public bool TryCross(double forwardMetres, out double upMetres, out double rightMetres)
        {
            Require.Finite(forwardMetres, nameof(forwardMetres));
            for (int i = 0; i + 1 < _positions.Length; i++)
            {
                Vector3d p0 = _positions[i], p1 = _positions[i + 1];
                if (p0.X < forwardMetres && p1.X >= forwardMetres)
                {
                    double h = _times[i + 1] - _times[i];
                    Vector3d m0 = _velocities[i] * h, m1 = _velocities[i + 1] * h;
                    double lo = 0, hi = 1;
                    for (int k = 0; k < 60; k++)
                    {
                        double mid = 0.5 * (lo + hi);
                        if (Hermite(p0.X, p1.X, m0.X, m1.X, mid) < forwardMetres)
                        {
                            lo = mid;
                        }
                        else
                        {
                            hi = mid;
                        }
                    }

                    double s = 0.5 * (lo + hi);
                    upMetres = Hermite(p0.Z, p1.Z, m0.Z, m1.Z, s);
                    rightMetres = Hermite(p0.Y, p1.Y, m0.Y, m1.Y, s);
                    return true;
                }
            }

            upMetres = 0;
            rightMetres = 0;
            return false;
        }

        private static double Hermite(double p0, double p1, double m0, double m1, double s)
        {
            double s2 = s * s, s3 = s2 * s;
            return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"carry {CarryMetres:0.##} m ({CarryYards:0.#} yd), apex {ApexMetres:0.##} m, {FlightTimeSeconds:0.##} s, lands at {LandingAngleDegrees:0.#} deg " +
            $"and {LandingSpeedMetresPerSecond:0.#} m/s, side {SideMetres:0.##} m, curve {CurveMetres:0.##} m{(Landed ? string.Empty : " (did not land)")}";
    }
}
