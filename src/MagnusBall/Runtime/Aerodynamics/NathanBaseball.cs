namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Baseball drag after Nathan: C_D = 0.3008 + 0.0292 (spin in rpm / 1000), linear in the spin rate.
    /// </summary>
    /// <remarks>
    /// Source: A. M. Nathan's trajectory calculator (University of Illinois, "TrajectoryCalculator"), as ported
    /// in pybaseball (secondary transcription). Continuous and smooth in the spin; independent of speed (the
    /// calculator ignores the drag crisis, which for a baseball lies below game speeds).
    /// </remarks>
    public sealed class NathanBaseballDrag : IDragModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static NathanBaseballDrag Instance { get; } = new NathanBaseballDrag();

        /// <summary>
        /// Creates the law. It holds no state, so every instance gives the same numbers as <see cref="Instance"/>
        /// (which the presets and the flight kernel use; the kernel specialises on the type, not the instance).
        /// </summary>
        internal NathanBaseballDrag()
        {
        }

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) => Evaluate(conditions.SpinRpm);

        /// <summary>C_D at <paramref name="spinRpm"/> revolutions per minute.</summary>
        /// <param name="spinRpm">Spin rate |w|, rpm (&gt;= 0).</param>
        internal static double Evaluate(double spinRpm) => 0.3008 + 0.0292 * (spinRpm / 1000.0);

        /// <inheritdoc />
        public override string ToString() => "NathanBaseballDrag";
    }

    /// <summary>
    /// Baseball lift after Nathan: C_L = 1.120 S / (0.583 + 2.333 S), S = S_perp = r|w x v_hat|/s.
    /// </summary>
    /// <remarks>
    /// Source: A. M. Nathan's trajectory calculator, as ported in pybaseball (secondary transcription). C_L is
    /// 0 at S = 0, rises with slope 1.92 there, and saturates at 1.120/2.333 = 0.48. Continuous and smooth.
    /// </remarks>
    public sealed class NathanBaseballLift : ILiftModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static NathanBaseballLift Instance { get; } = new NathanBaseballLift();

        /// <summary>
        /// Creates the law. It holds no state, so every instance gives the same numbers as <see cref="Instance"/>
        /// (which the presets and the flight kernel use; the kernel specialises on the type, not the instance).
        /// </summary>
        internal NathanBaseballLift()
        {
        }

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter);

        /// <summary>C_L at <paramref name="spinParameter"/> (0 for S &lt;= 0).</summary>
        /// <param name="spinParameter">S_perp.</param>
        internal static double Evaluate(double spinParameter) =>
            !(spinParameter > 0) ? 0.0
            : spinParameter < 1e300 ? 1.120 * spinParameter / (0.583 + 2.333 * spinParameter)
            : 1.120 / (0.583 / spinParameter + 2.333); // the same, without 2.333 S overflowing

        /// <inheritdoc />
        public override string ToString() => "NathanBaseballLift";
    }
}
