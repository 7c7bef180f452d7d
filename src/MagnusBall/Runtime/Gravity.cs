namespace MagnusBall
{
    /// <summary>
    /// Gravity vectors for the common frames. The library itself never assumes an axis is up: a
    /// <see cref="FlightModel"/> takes gravity as a vector and derives "up" as its opposite.
    /// </summary>
    public static class Gravity
    {
        /// <summary>Standard acceleration of gravity, 9.80665 m/s^2 (CGPM 1901).</summary>
        internal const double Standard = 9.80665;

        /// <summary>Standard gravity in a z-up frame (the thesis's): (0, 0, -9.80665) m/s^2.</summary>
        public static Vector3d ZUp => new Vector3d(0, 0, -Standard);

        /// <summary>Standard gravity in a y-up frame (Unity's, Godot's): (0, -9.80665, 0) m/s^2.</summary>
        public static Vector3d YUp => new Vector3d(0, -Standard, 0);

        /// <summary>Gravity of magnitude <paramref name="magnitude"/> pointing against <paramref name="up"/>.</summary>
        /// <param name="up">The frame's up direction (any non-zero finite vector; it is normalised).</param>
        /// <param name="magnitude">|g|, m/s^2; finite and &gt;= 0.</param>
        /// <exception cref="System.ArgumentException">up is zero or not finite, or magnitude is out of range.</exception>
        public static Vector3d Along(Vector3d up, double magnitude = Standard)
        {
            Require.NonZero(up, nameof(up));
            Require.NonNegative(magnitude, nameof(magnitude));
            return up.NormalizedOrZero() * -magnitude;
        }
    }
}
