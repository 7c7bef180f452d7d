using System;

namespace MagnusBall.Shots
{
    /// <summary>A ball speed in the unit a sport publishes it in: m/s, km/h (tennis, soccer) or mph (golf, baseball).</summary>
    public readonly struct Speed
    {
        /// <summary>1 mph in m/s: 0.44704 exactly (1 mile = 1609.344 m).</summary>
        private const double MetresPerSecondPerMph = 0.44704;

        private Speed(double metresPerSecond) => MetresPerSecond = metresPerSecond;

        /// <summary>The speed, m/s.</summary>
        public double MetresPerSecond { get; }

        /// <summary>A speed in metres per second.</summary>
        /// <param name="metresPerSecond">m/s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">The speed is negative or not finite.</exception>
        public static Speed FromMetresPerSecond(double metresPerSecond) =>
            new Speed(Require.NonNegative(metresPerSecond, nameof(metresPerSecond)));

        /// <summary>A speed in kilometres per hour (1 km/h = 1/3.6 m/s).</summary>
        /// <param name="kilometresPerHour">km/h; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">The speed is negative or not finite.</exception>
        public static Speed FromKilometresPerHour(double kilometresPerHour) =>
            new Speed(Require.NonNegative(kilometresPerHour, nameof(kilometresPerHour)) / 3.6);

        /// <summary>A speed in miles per hour (1 mph = 0.44704 m/s).</summary>
        /// <param name="milesPerHour">mph; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">The speed is negative or not finite.</exception>
        public static Speed FromMilesPerHour(double milesPerHour) =>
            new Speed(Require.NonNegative(milesPerHour, nameof(milesPerHour)) * MetresPerSecondPerMph);

        internal static double ToMph(double metresPerSecond) => metresPerSecond / MetresPerSecondPerMph;

        /// <inheritdoc />
        public override string ToString() => $"{MetresPerSecond:0.###} m/s";
    }
}
