namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// A drag law linear in the spin parameter, C_D = c0 + slope S with S = r|w|/s (c0 may depend on the other
    /// conditions). The model's overflow-safe path uses it: where S overflows (a finite spin at a vanishing speed)
    /// k s^2 slope S is formed as k s slope r |w|, finite wherever the true drag is.
    /// </summary>
    internal interface ISpinLinearDrag
    {
        /// <summary>The slope of C_D in S.</summary>
        double SpinSlope { get; }

        /// <summary>c0: C_D without its spin term, at these conditions.</summary>
        /// <param name="conditions">The conditions.</param>
        double CoefficientWithoutSpin(in AeroConditions conditions);
    }
}
