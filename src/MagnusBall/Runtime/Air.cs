namespace MagnusBall
{
    /// <summary>
    /// The air a ball flies through: its density, its viscosity and the wind (uniform, or growing with height
    /// along a <see cref="LogarithmicWindProfile"/>). Immutable and safe to share.
    /// </summary>
    /// <remarks>
    /// Every aerodynamic force is computed on the air-relative velocity v - wind (drag, lift and the spin
    /// parameter alike), so a ball moving exactly with the wind feels no drag and no Magnus force. Build air
    /// from the weather with <see cref="FromWeather"/> or from altitude with <see cref="AtAltitude"/>
    /// (see <see cref="Atmosphere"/> for the formulas).
    /// </remarks>
    public sealed class Air
    {
        /// <summary>Density of dry air at 15 degC and 101325 Pa (ISA sea level), 1.225 kg/m^3.</summary>
        internal const double SeaLevelDensity = 1.225;

        /// <summary>
        /// The default dynamic viscosity, 1.81e-5 Pa s (used for Reynolds numbers): air near 20 degC (Sutherland's law gives
        /// 1.8134e-5 there), not the ISA's 15 degC value 1.7894e-5, which <see cref="AtAltitude"/> and <see cref="FromWeather"/>
        /// compute. Kept as the default because the presets' Reynolds-dependent laws were checked and calibrated with it; with
        /// it a Reynolds number is 1.1 % below the ISA's at 15 degC.
        /// </summary>
        internal const double SeaLevelDynamicViscosity = 1.81e-5;

        /// <summary>
        /// Creates air of a given density, with an optional uniform wind.
        /// </summary>
        /// <param name="density">Density, kg/m^3; finite and &gt;= 0 (0 is a vacuum).</param>
        /// <param name="wind">Uniform wind velocity, m/s; finite. Default: still air.</param>
        /// <param name="dynamicViscosity">Dynamic viscosity, Pa s; finite and &gt; 0.</param>
        /// <exception cref="System.ArgumentException">A value is outside its range; the message names it.</exception>
        public Air(double density, Vector3d wind = default, double dynamicViscosity = SeaLevelDynamicViscosity)
            : this(density, wind, dynamicViscosity, null)
        {
        }

        private Air(double density, Vector3d wind, double dynamicViscosity, LogarithmicWindProfile? windProfile)
        {
            Require.NonNegative(density, nameof(density));
            Require.Finite(wind, nameof(wind));
            Require.Positive(dynamicViscosity, nameof(dynamicViscosity));
            Density = density;
            Wind = wind;
            DynamicViscosity = dynamicViscosity;
            WindProfile = windProfile;
        }

        /// <summary>Density, kg/m^3.</summary>
        public double Density { get; }

        /// <summary>
        /// Wind velocity, m/s: the uniform wind, or with a <see cref="WindProfile"/> the wind at its reference
        /// height. Use <see cref="WindAt"/> for the wind at a point.
        /// </summary>
        public Vector3d Wind { get; }

        /// <summary>The wind's variation with height, or null for a uniform wind.</summary>
        public LogarithmicWindProfile? WindProfile { get; }

        /// <summary>Dynamic viscosity, Pa s.</summary>
        public double DynamicViscosity { get; }

        /// <summary>Still dry air at ISA sea level density (1.225 kg/m^3), with the default viscosity <see cref="SeaLevelDynamicViscosity"/> (near 20 degC; <c>AtAltitude(0)</c> has the ISA's).</summary>
        public static Air SeaLevel { get; } = new Air(SeaLevelDensity);

        /// <summary>No air at all: density 0, so no drag and no lift whatever the models say.</summary>
        public static Air Vacuum { get; } = new Air(0);

        /// <summary>A copy of this air with another uniform wind.</summary>
        /// <param name="wind">Wind velocity, m/s; finite.</param>
        public Air WithWind(Vector3d wind) => new Air(Density, wind, DynamicViscosity);

        /// <summary>
        /// A copy of this air whose wind follows a logarithmic profile with height: <paramref name="referenceWind"/>
        /// at <paramref name="referenceHeight"/> above the ground, ln(z/z0)/ln(z_ref/z0) times that at height z,
        /// zero at or below the roughness length z0. See <see cref="LogarithmicWindProfile"/>.
        /// </summary>
        /// <param name="referenceWind">Wind velocity at the reference height, m/s; finite.</param>
        /// <param name="referenceHeight">Reference (anemometer) height, m; finite and &gt; roughnessLength. Usually 10 m.</param>
        /// <param name="roughnessLength">Roughness length z0, m; finite and &gt; 0 (0.03 m open grass, 0.005 m mown turf).</param>
        /// <param name="groundPoint">Any point on the ground plane, m; finite. Default: the origin.</param>
        /// <exception cref="System.ArgumentException">A value is outside its range; the message names it.</exception>
        public Air WithLogarithmicWind(
            Vector3d referenceWind,
            double referenceHeight = LogarithmicWindProfile.StandardReferenceHeight,
            double roughnessLength = LogarithmicWindProfile.OpenGrassRoughnessLength,
            Vector3d groundPoint = default) =>
            new Air(Density, referenceWind, DynamicViscosity, new LogarithmicWindProfile(referenceHeight, roughnessLength, groundPoint));

        /// <summary>
        /// The wind at <paramref name="position"/>, m/s. Uniform wind: <see cref="Wind"/> everywhere. With a
        /// profile: the wind at the point's height along <paramref name="up"/>; when <paramref name="up"/> is
        /// zero (no gravity, so no height) the reference wind. Allocates nothing.
        /// </summary>
        /// <param name="position">The point, m.</param>
        /// <param name="up">The unit up vector (a <see cref="FlightModel"/>'s <see cref="FlightModel.Up"/>), or zero.</param>
        public Vector3d WindAt(in Vector3d position, in Vector3d up)
        {
            LogarithmicWindProfile? profile = WindProfile;
            if (profile is null || up.LengthSquared == 0)
            {
                return Wind;
            }

            return Overflow.Multiply(Wind, profile.Factor(profile.HeightOf(position, up)));
        }

        /// <summary>
        /// Air from the weather: moist-air density from temperature, pressure and relative humidity
        /// (Tetens' saturation vapour pressure), viscosity by Sutherland's law; see <see cref="Atmosphere"/>.
        /// 15 degC, 101325 Pa, dry: 1.2250 kg/m^3.
        /// </summary>
        /// <param name="temperatureCelsius">Temperature, degC; in [-90, 60].</param>
        /// <param name="pressurePascals">Station (not sea-level-corrected) pressure, Pa; finite and at least 5000 (the air at 20 km).</param>
        /// <param name="relativeHumidity">Relative humidity as a fraction in [0, 1]; default 0 (dry).</param>
        /// <param name="wind">Uniform wind, m/s; finite. Default: still air.</param>
        /// <exception cref="System.ArgumentException">A value is outside its range; the message names it.</exception>
        public static Air FromWeather(double temperatureCelsius, double pressurePascals, double relativeHumidity = 0, Vector3d wind = default) =>
            new Air(
                Atmosphere.MoistAirDensity(temperatureCelsius, pressurePascals, relativeHumidity),
                wind,
                Atmosphere.DynamicViscosity(temperatureCelsius));

        /// <summary>
        /// Air at an altitude: the ISA standard-atmosphere pressure there (ISO 2533), at the ISA temperature
        /// or at a given temperature, with optional humidity. Denver (1609 m): 1.047 kg/m^3 at the ISA's
        /// 4.5 degC (14.6 % below sea level's 1.225); at sea level's 15 degC, 1.009 kg/m^3 (17.7 % below).
        /// </summary>
        /// <param name="altitudeMetres">Altitude above mean sea level, m; in [-1000, 20000].</param>
        /// <param name="temperatureCelsius">Temperature, degC, in [-90, 60]; null for the ISA temperature at that altitude.</param>
        /// <param name="relativeHumidity">Relative humidity as a fraction in [0, 1]; default 0 (dry).</param>
        /// <param name="wind">Uniform wind, m/s; finite. Default: still air.</param>
        /// <exception cref="System.ArgumentException">A value is outside its range; the message names it.</exception>
        public static Air AtAltitude(double altitudeMetres, double? temperatureCelsius = null, double relativeHumidity = 0, Vector3d wind = default)
        {
            double pressure = Atmosphere.StandardPressure(altitudeMetres);
            double temperature = temperatureCelsius ?? Atmosphere.StandardTemperatureCelsius(altitudeMetres);
            Require.InRange(temperature, Atmosphere.MinimumTemperatureCelsius, Atmosphere.MaximumTemperatureCelsius, nameof(temperatureCelsius));
            double vapour = Atmosphere.VapourPressure(temperature, relativeHumidity);
            if (vapour >= pressure)
            {
                // The caller gave no pressure: the humidity is what cannot be at this altitude and temperature.
                throw new System.ArgumentOutOfRangeException(
                    nameof(relativeHumidity),
                    relativeHumidity,
                    $"relativeHumidity must be below {Require.Format(pressure / Atmosphere.SaturationVapourPressure(temperature))} at {Require.Format(altitudeMetres)} m and " +
                    $"{Require.Format(temperature)} degC (the vapour pressure must stay below the standard pressure there, {Require.Format(pressure)} Pa); " +
                    $"got {Require.Format(relativeHumidity)}, a vapour pressure of {Require.Format(vapour)} Pa.");
            }

            return FromWeather(temperature, pressure, relativeHumidity, wind);
        }

        /// <inheritdoc />
        public override string ToString() =>
            WindProfile is null
                ? $"Air(rho={Density:R} kg/m^3, wind={Wind})"
                : $"Air(rho={Density:R} kg/m^3, wind={Wind} at {WindProfile})";
    }
}
