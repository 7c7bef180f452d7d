using System;
using System.Collections.Generic;
using System.Globalization;
using MagnusBall.Presets;

namespace MagnusBall.Shots
{
    /// <summary>
    /// What real balls of a sport are and do: the mass and radius the sport's rules allow, and the highest launch speed and
    /// spin rate any real ball of the sport reaches (the published records, rounded up). <see cref="Check(double, double, double, double)"/>
    /// turns a value outside them into a warning that names the likely unit mistake (grams for kilograms, rpm typed as
    /// rad/s, km/h for m/s). The values are tabulated with their sources in docs/shots.md; the CLI prints these warnings.
    /// </summary>
    public sealed class SportLimits
    {
        private readonly string _sport, _ballSource, _speedSource, _spinSource;

        private SportLimits(
            string sport, double minMass, double maxMass, double minRadius, double maxRadius, double maxSpeed, double maxSpin,
            string ballSource, string speedSource, string spinSource)
        {
            _ballSource = ballSource;
            _speedSource = speedSource;
            _spinSource = spinSource;
            _sport = sport;
            MinimumMassKilograms = minMass;
            MaximumMassKilograms = maxMass;
            MinimumRadiusMetres = minRadius;
            MaximumRadiusMetres = maxRadius;
            MaximumSpeedMetresPerSecond = maxSpeed;
            MaximumSpinRpm = maxSpin;
            Source = ballSource + "; " + speedSource + "; " + spinSource;
        }

        // Radii from the rules' circumferences (C / 2 pi) or diameters (D / 2).
        private static readonly SportLimits TennisLimits = new SportLimits(
            "tennis ball", 0.0560, 0.0594, 0.0327, 0.0343, 75, 6000,
            "ITF Rules of Tennis, appendix I (56.0-59.4 g, 6.54-6.86 cm)", "fastest recorded serve 263 km/h = 73 m/s (S. Groth, 2012)",
            "heaviest measured topspin near 5,000 rpm (R. Nadal's forehand, J. Yandell, tennisplayer.net)");

        private static readonly SportLimits SoccerLimits = new SportLimits(
            "soccer ball", 0.410, 0.450, 0.68 / (2 * Math.PI), 0.70 / (2 * Math.PI), 60, 1200,
            "IFAB Laws of the Game, law 2 (410-450 g, 68-70 cm round)", "hardest recorded shots about 210 km/h = 58 m/s",
            "measured free kicks spin at most about 10 rev/s = 600 rpm (Goff & Carre 2009, Am. J. Phys. 77:1020), limit set at twice that");

        private static readonly SportLimits BaseballLimits = new SportLimits(
            "baseball", 0.1417, 0.1488, 0.2286 / (2 * Math.PI), 0.23495 / (2 * Math.PI), 56, 5000,
            "MLB Official Baseball Rules 3.01 (5-5.25 oz, 9-9.25 in round)",
            "fastest tracked pitch 105.8 mph, hardest-hit balls about 123 mph (Statcast), limit 125 mph = 56 m/s",
            "pitches spin up to about 3,500 rpm (Statcast), batted balls less than 5,000 rpm (A. M. Nathan)");

        private static readonly SportLimits GolfLimits = new SportLimits(
            "golf ball", 0.040, 0.04593, 0.021335, 0.022, 105, 12000,
            "USGA/R&A equipment rules (at most 45.93 g, at least 42.67 mm; real balls weigh more than 40 g and measure under 44 mm)",
            "long-drive ball speeds stay under about 230 mph = 103 m/s", "wedge shots spin up to about 11,000 rpm (TrackMan)");

        private static readonly SportLimits TableTennisLimits = new SportLimits(
            "table-tennis ball", 0.00267, 0.00277, 0.01975, 0.02025, 40, 10000,
            "ITTF Handbook 2.3 (40 mm, 2.7 g) and ITTF technical leaflet T3 (2.67-2.77 g, 39.5-40.5 mm)", "smashes stay under about 32 m/s",
            "the fastest loops spin about 150 rev/s = 9,000 rpm");

        private static readonly SportLimits BasketballLimits = new SportLimits(
            "basketball", 0.567, 0.650, 0.749 / (2 * Math.PI), 0.780 / (2 * Math.PI), 25, 600,
            "FIBA Official Basketball Rules, equipment (size 7: 567-650 g, 749-780 mm round)", "throws stay under about 20 m/s",
            "shots spin 2-3 rev/s and a ball spun on a finger about 10 rev/s = 600 rpm");

        /// <summary>
        /// The limits of <paramref name="preset"/>'s sport (by its name: tennis, soccer, baseball, golf, table-tennis,
        /// basketball and their variants, such as golf-smits-smith), or null for a preset of another name.
        /// </summary>
        /// <param name="preset">A preset (<see cref="SportPresets"/>).</param>
        /// <exception cref="ArgumentNullException">preset is null.</exception>
        public static SportLimits? For(SportPreset preset)
        {
            string name = Require.NotNull(preset, nameof(preset)).Name;
            return name.StartsWith("tennis", StringComparison.OrdinalIgnoreCase) ? TennisLimits
                : name.StartsWith("table-tennis", StringComparison.OrdinalIgnoreCase) ? TableTennisLimits
                : name.StartsWith("soccer", StringComparison.OrdinalIgnoreCase) ? SoccerLimits
                : name.StartsWith("baseball", StringComparison.OrdinalIgnoreCase) ? BaseballLimits
                : name.StartsWith("golf", StringComparison.OrdinalIgnoreCase) ? GolfLimits
                : name.StartsWith("basketball", StringComparison.OrdinalIgnoreCase) ? BasketballLimits
                : null;
        }

        /// <summary>The lightest ball the sport's rules allow, kg.</summary>
        public double MinimumMassKilograms { get; }

        /// <summary>The heaviest ball the sport's rules allow, kg.</summary>
        public double MaximumMassKilograms { get; }

        /// <summary>The smallest radius the sport's rules allow, m.</summary>
        public double MinimumRadiusMetres { get; }

        /// <summary>The largest radius the sport's rules allow, m.</summary>
        public double MaximumRadiusMetres { get; }

        /// <summary>The highest launch speed a real ball of the sport reaches (its record, rounded up), m/s.</summary>
        public double MaximumSpeedMetresPerSecond { get; }

        /// <summary>The highest spin rate a real ball of the sport reaches, rpm.</summary>
        public double MaximumSpinRpm { get; }

        /// <summary>Where the limits come from.</summary>
        public string Source { get; }

        /// <summary>
        /// Warnings for a ball or shot outside what the sport's real balls are and do, each one line naming the value, the range,
        /// the source and the likely unit mistake; empty when all is plausible.
        /// </summary>
        /// <param name="massKilograms">The ball's mass, kg; finite, &gt; 0.</param>
        /// <param name="radiusMetres">The ball's radius, m; finite, &gt; 0.</param>
        /// <param name="speedMetresPerSecond">The launch speed, m/s; finite, &gt;= 0.</param>
        /// <param name="spinRpm">The spin rate, rpm; finite, &gt;= 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is outside its range (the message names it).</exception>
        public IReadOnlyList<string> Check(double massKilograms, double radiusMetres, double speedMetresPerSecond, double spinRpm)
        {
            Require.Positive(massKilograms, nameof(massKilograms));
            Require.Positive(radiusMetres, nameof(radiusMetres));
            Require.NonNegative(speedMetresPerSecond, nameof(speedMetresPerSecond));
            Require.NonNegative(spinRpm, nameof(spinRpm));
            var warnings = new List<string>();
            if (massKilograms < MinimumMassKilograms || massKilograms > MaximumMassKilograms)
            {
                warnings.Add($"mass {F(massKilograms)} kg is outside a {_sport}'s {F(MinimumMassKilograms)}-{F(MaximumMassKilograms)} kg" +
                    (Within(massKilograms / 1000, MinimumMassKilograms, MaximumMassKilograms) ? $"; a mass in grams? ({F(massKilograms)} g = {F(massKilograms / 1000)} kg)" : string.Empty) +
                    $" (source: {_ballSource})");
            }

            if (radiusMetres < MinimumRadiusMetres || radiusMetres > MaximumRadiusMetres)
            {
                string hint = Within(radiusMetres / 2, MinimumRadiusMetres, MaximumRadiusMetres) ? "; a diameter? (the radius is half of it)"
                    : Within(radiusMetres / 1000, MinimumRadiusMetres, MaximumRadiusMetres) ? $"; a radius in millimetres? ({F(radiusMetres)} mm = {F(radiusMetres / 1000)} m)"
                    : Within(radiusMetres / 100, MinimumRadiusMetres, MaximumRadiusMetres) ? $"; a radius in centimetres? ({F(radiusMetres)} cm = {F(radiusMetres / 100)} m)"
                    : Within(radiusMetres / 2000, MinimumRadiusMetres, MaximumRadiusMetres) ? "; a diameter in millimetres?"
                    : string.Empty;
                warnings.Add($"radius {F(radiusMetres)} m is outside a {_sport}'s {F(MinimumRadiusMetres)}-{F(MaximumRadiusMetres)} m{hint} (source: {_ballSource})");
            }

            if (speedMetresPerSecond > MaximumSpeedMetresPerSecond)
            {
                warnings.Add($"speed {F(speedMetresPerSecond)} m/s is above the fastest a {_sport} flies, {F(MaximumSpeedMetresPerSecond)} m/s" +
                    UnitHint(speedMetresPerSecond) +
                    $" (source: {_speedSource})");
            }

            if (spinRpm > MaximumSpinRpm)
            {
                double radiansPerSecond = MagnusBall.Spin.FromRpm(spinRpm);
                warnings.Add($"spin {F(spinRpm)} rpm ({F(radiansPerSecond)} rad/s) is above the most a {_sport} spins, {F(MaximumSpinRpm)} rpm" +
                    (radiansPerSecond <= MaximumSpinRpm ? $"; a rate in rpm typed where rad/s is meant? ({F(radiansPerSecond)} rpm = {F(MagnusBall.Spin.FromRpm(radiansPerSecond))} rad/s)" : string.Empty) +
                    $" (source: {_spinSource})");
            }

            return warnings;
        }

        /// <summary>Warnings for <paramref name="model"/>'s ball launched as <paramref name="launch"/> (its speed and spin rate); see <see cref="Check(double, double, double, double)"/>.</summary>
        /// <param name="model">The flight model (its ball).</param>
        /// <param name="launch">The launch state; finite.</param>
        /// <exception cref="ArgumentException">model is null or the state is not finite.</exception>
        public IReadOnlyList<string> Check(FlightModel model, in FlightState launch)
        {
            Require.NotNull(model, nameof(model));
            Require.FiniteState(launch, nameof(launch));
            return Check(model.Ball.Mass, model.Ball.Radius, launch.Velocity.Length, MagnusBall.Spin.ToRpm(launch.AngularVelocity.Length));
        }

        private static bool Within(double value, double min, double max) => value >= min && value <= max;

        private static string F(double value) => value.ToString("0.####", CultureInfo.InvariantCulture);

        // A speed that is plausible once read as km/h or as mph: the conversions that bring it within the sport's range.
        private string UnitHint(double speed)
        {
            double fromKmh = speed / 3.6, fromMph = speed * 0.44704;
            string? kmh = fromKmh <= MaximumSpeedMetresPerSecond ? $"{F(speed)} km/h = {F(fromKmh)} m/s" : null;
            string? mph = fromMph <= MaximumSpeedMetresPerSecond ? $"{F(speed)} mph = {F(fromMph)} m/s" : null;
            return kmh != null && mph != null ? $"; a speed in km/h or mph? ({kmh}; {mph})"
                : kmh != null ? $"; a speed in km/h? ({kmh})"
                : mph != null ? $"; a speed in mph? ({mph})"
                : string.Empty;
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"SportLimits({_sport}: {F(MinimumMassKilograms)}-{F(MaximumMassKilograms)} kg, {F(MinimumRadiusMetres)}-{F(MaximumRadiusMetres)} m, " +
            $"<= {F(MaximumSpeedMetresPerSecond)} m/s, <= {F(MaximumSpinRpm)} rpm)";
    }
}
