namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// A drag coefficient that does not depend on speed or spin, as in the seed thesis
    /// (Agrawal 2023, eqs. 4-5, c_d = 0.55 for its tennis cases).
    /// </summary>
    public sealed class ConstantDrag : IDragModel
    {
        /// <summary>Creates the law C_D = <paramref name="dragCoefficient"/>.</summary>
        /// <param name="dragCoefficient">C_D, finite and &gt;= 0.</param>
        /// <exception cref="System.ArgumentOutOfRangeException">C_D is negative or not finite.</exception>
        public ConstantDrag(double dragCoefficient)
        {
            Value = Require.NonNegative(dragCoefficient, nameof(dragCoefficient));
        }

        /// <summary>The constant C_D.</summary>
        internal double Value { get; }

        /// <summary>The seed thesis's reverse-engineered tennis drag coefficient, c_d = 0.55 (Agrawal 2023).</summary>
        public static ConstantDrag ThesisTennis { get; } = new ConstantDrag(0.55);

        /// <summary>
        /// Cross &amp; Lindsey's free-flight tennis drag coefficient, C_D = 0.507 (+- 0.024), independent of
        /// speed and spin for 15-30 m/s and up to 2500 rpm.
        /// </summary>
        public static ConstantDrag CrossLindseyTennis { get; } = new ConstantDrag(0.507);

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) => Value;

        /// <inheritdoc />
        public override string ToString() => $"ConstantDrag({Value:R})";
    }

    /// <summary>
    /// A lift coefficient that does not depend on speed or spin, as in the seed thesis (Agrawal 2023, eq. 2,
    /// c_m = 0.175 for its tennis cases, after Javorova &amp; Ivanov 2018). Applied to the transverse spin:
    /// the force is 1/2 rho A C_L s^2 (w x v_hat)/|w|.
    /// </summary>
    public sealed class ConstantLift : ILiftModel
    {
        /// <summary>Creates the law C_L = <paramref name="liftCoefficient"/>.</summary>
        /// <param name="liftCoefficient">C_L, finite (negative values model an inverse Magnus effect).</param>
        /// <exception cref="System.ArgumentOutOfRangeException">C_L is not finite.</exception>
        public ConstantLift(double liftCoefficient)
        {
            Value = Require.Finite(liftCoefficient, nameof(liftCoefficient));
        }

        /// <summary>The constant C_L.</summary>
        internal double Value { get; }

        /// <summary>The seed thesis's reverse-engineered tennis Magnus coefficient, c_m = 0.175 (Agrawal 2023).</summary>
        public static ConstantLift ThesisTennis { get; } = new ConstantLift(0.175);

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Value;

        /// <inheritdoc />
        public override string ToString() => $"ConstantLift({Value:R})";
    }

    /// <summary>
    /// Lift linear in the transverse spin parameter, C_L = k S_perp. Cross (2020, Sports Engineering 23:9)
    /// uses k = 0.6 with C_D = 0.55 for tennis groundstrokes (secondary transcription).
    /// </summary>
    public sealed class LinearSpinLift : ILiftModel
    {
        /// <summary>Creates the law C_L = <paramref name="slope"/> S_perp.</summary>
        /// <param name="slope">k, finite.</param>
        /// <exception cref="System.ArgumentOutOfRangeException">k is not finite.</exception>
        public LinearSpinLift(double slope)
        {
            Slope = Require.Finite(slope, nameof(slope));
        }

        /// <summary>The slope k in C_L = k S_perp.</summary>
        internal double Slope { get; }

        /// <summary>Cross (2020)'s tennis groundstroke law, C_L = 0.6 S.</summary>
        public static LinearSpinLift Cross2020Tennis { get; } = new LinearSpinLift(0.6);

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Overflow.Multiply(Slope, conditions.TransverseSpinParameter);

        /// <inheritdoc />
        public override string ToString() => $"LinearSpinLift(k={Slope:R})";
    }
}
