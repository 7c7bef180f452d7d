namespace MagnusBall.Shots
{
    /// <summary>
    /// A pitch where it crosses the front of home plate, in Statcast's terms and units (from the catcher's perspective:
    /// positive side is the catcher's right, the first-base side), and its break: the movement the spin gives it against the
    /// same pitch without the Magnus force, from the release to the front of the plate (Statcast's induced vertical break and
    /// horizontal break, inches). Made by <see cref="ShotFlyer.Pitch"/>.
    /// </summary>
    public readonly struct PitchResult
    {
        private const double MetresPerFoot = 0.3048, MetresPerInch = 0.0254;

        internal PitchResult(double time, double speed, double height, double side, double verticalBreak, double horizontalBreak)
        {
            CrossesPlate = true;
            PlateTimeSeconds = time;
            PlateSpeedMph = Speed.ToMph(speed);
            PlateHeightFeet = height / MetresPerFoot;
            PlateSideFeet = side / MetresPerFoot;
            InducedVerticalBreakInches = verticalBreak / MetresPerInch;
            HorizontalBreakInches = horizontalBreak / MetresPerInch;
        }

        /// <summary>True when the pitch reaches the front of the plate before it lands; false (and every number 0) when it does not.</summary>
        public bool CrossesPlate { get; }

        /// <summary>Time from the release to the front of the plate, s.</summary>
        public double PlateTimeSeconds { get; }

        /// <summary>Speed at the front of the plate, mph.</summary>
        public double PlateSpeedMph { get; }

        /// <summary>Height of the ball's centre above the field at the front of the plate, ft (Statcast's plate_z).</summary>
        public double PlateHeightFeet { get; }

        /// <summary>Side of the ball's centre from the middle of the plate, ft, positive to the catcher's right (Statcast's plate_x).</summary>
        public double PlateSideFeet { get; }

        /// <summary>Induced vertical break, inches: the rise (positive) or drop (negative) the spin gives against a pitch without it (Statcast's induced vertical break).</summary>
        public double InducedVerticalBreakInches { get; }

        /// <summary>Horizontal break, inches, positive to the catcher's right, the first-base side (Statcast's pfx_x, in inches).</summary>
        public double HorizontalBreakInches { get; }

        /// <inheritdoc />
        public override string ToString() => !CrossesPlate ? "PitchResult(does not reach the plate)"
            : $"PitchResult(plate at {PlateTimeSeconds:0.###} s, {PlateSpeedMph:0.#} mph, height {PlateHeightFeet:0.##} ft, side {PlateSideFeet:0.##} ft, " +
              $"IVB {InducedVerticalBreakInches:0.#} in, HB {HorizontalBreakInches:0.#} in)";
    }
}
