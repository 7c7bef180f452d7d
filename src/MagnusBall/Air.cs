namespace MagnusBall
{
    /// <summary>
    /// The air a ball flies through: its density and a uniform wind. Immutable and safe to share.
    /// </summary>
    /// <remarks>
    /// Every aerodynamic force is computed on the air-relative velocity v - wind (drag, lift and the spin
    /// parameter alike), so a ball moving exactly with the wind feels no drag and no Magnus force.
    /// </remarks>
    public sealed class Air
    {
        /// <summary>Density of dry air at 15 degC and 101325 Pa (ISA sea level), 1.225 kg/m^3.</summary>
        public const double SeaLevelDensity = 1.225;

        /// <summary>Dynamic viscosity of air at 15 degC, 1.81e-5 Pa s (used for Reynolds numbers).</summary>
        public const double SeaLevelDynamicViscosity = 1.81e-5;

        /// <summary>
        /// Creates air of a given density, with an optional uniform wind.
        /// </summary>
        /// <param name="density">Density, kg/m^3; finite and &gt;= 0 (0 is a vacuum).</param>
        /// <param name="wind">Uniform wind velocity, m/s; finite. Default: still air.</param>
        /// <param name="dynamicViscosity">Dynamic viscosity, Pa s; finite and &gt; 0.</param>
        /// <exception cref="System.ArgumentException">A value is outside its range; the message names it.</exception>
        public Air(double density, Vector3d wind = default, double dynamicViscosity = SeaLevelDynamicViscosity)
        {
            Require.NonNegative(density, nameof(density));
            Require.Finite(wind, nameof(wind));
            Require.Positive(dynamicViscosity, nameof(dynamicViscosity));
            Density = density;
            Wind = wind;
            DynamicViscosity = dynamicViscosity;
        }

        /// <summary>Density, kg/m^3.</summary>
        public double Density { get; }

        /// <summary>Uniform wind velocity, m/s.</summary>
        public Vector3d Wind { get; }

        /// <summary>Dynamic viscosity, Pa s.</summary>
        public double DynamicViscosity { get; }

        /// <summary>Still dry air at ISA sea level (1.225 kg/m^3).</summary>
        public static Air SeaLevel { get; } = new Air(SeaLevelDensity);

        /// <summary>No air at all: density 0, so no drag and no lift whatever the models say.</summary>
        public static Air Vacuum { get; } = new Air(0);

        /// <summary>A copy of this air with another uniform wind.</summary>
        /// <param name="wind">Wind velocity, m/s; finite.</param>
        public Air WithWind(Vector3d wind) => new Air(Density, wind, DynamicViscosity);

        /// <inheritdoc />
        public override string ToString() => $"Air(rho={Density:R} kg/m^3, wind={Wind})";
    }
}
