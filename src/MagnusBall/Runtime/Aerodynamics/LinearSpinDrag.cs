namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Drag linear in the spin parameter, C_D = a + b S with S = r|w|/s.
    /// </summary>
    /// <remarks>
    /// Golf: Smits &amp; Smith (1994, Science and Golf II; secondary transcription) give a = 0.24, b = 0.18 for
    /// the supercritical range of a driven ball (Re above about 7e4); the origin of the spin term is not
    /// documented in the secondary source.
    /// </remarks>
    public sealed class LinearSpinDrag : IDragModel, ISpinLinearDrag
    {
        /// <summary>Creates the law C_D = <paramref name="intercept"/> + <paramref name="slope"/> S.</summary>
        /// <param name="intercept">a, C_D at zero spin; finite and &gt;= 0.</param>
        /// <param name="slope">b; finite and &gt;= 0 (so C_D never falls below a).</param>
        /// <exception cref="System.ArgumentOutOfRangeException">A value is out of range; the message names it.</exception>
        public LinearSpinDrag(double intercept, double slope)
        {
            Intercept = Require.NonNegative(intercept, nameof(intercept));
            Slope = Require.NonNegative(slope, nameof(slope));
        }

        /// <summary>a, C_D at zero spin.</summary>
        internal double Intercept { get; }

        /// <summary>b, the rise of C_D per unit spin parameter.</summary>
        internal double Slope { get; }

        /// <summary>Smits &amp; Smith's golf-ball drag, C_D = 0.24 + 0.18 S.</summary>
        public static LinearSpinDrag GolfSmitsSmith { get; } = new LinearSpinDrag(0.24, 0.18);

        /// <summary>
        /// Golf drag calibrated here to two TrackMan tour averages (2023): C_D = 0.1845 + 0.3533 S. With the
        /// Smits &amp; Smith lift table, 4 %/s spin decay and ISA sea-level air, (a, b) were solved so that the
        /// driver (171 mph, 10.4 deg, 2545 rpm) carries 282 yd and the 7-iron (123 mph, 16.1 deg, 7124 rpm)
        /// 176 yd. The <c>golf-linear-2023</c> preset's drag (the <c>golf</c> preset before issue 12, when this was
        /// its one calibrated parameter set); see docs/presets.md.
        /// </summary>
        public static LinearSpinDrag GolfTrackManCalibrated { get; } = new LinearSpinDrag(0.1845, 0.3533);

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) =>
            Intercept + Overflow.Multiply(Slope, conditions.SpinParameter);

        /// <inheritdoc />
        public override string ToString() => $"LinearSpinDrag({Intercept:R} + {Slope:R} S)";

        double ISpinLinearDrag.SpinSlope => Slope;

        double ISpinLinearDrag.CoefficientWithoutSpin(in AeroConditions conditions) => Intercept;
    }
}
