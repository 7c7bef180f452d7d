using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Stepanek's spin-dependent tennis drag, C_D = 0.508 + (22.053 + 4.196 (1/S)^2.5)^-0.4, with S = r|w|/s.
    /// </summary>
    /// <remarks>
    /// Source: Stepanek (1988), "The aerodynamics of tennis balls - the topspin lob", Am. J. Phys. 56:138,
    /// as used by Klvana (1998) and Cross. One secondary copy prints 22.503 for 22.053; 22.053 is used here.
    /// At S = 0 the law tends to 0.508; as S grows it rises toward 0.508 + 22.053^-0.4 = 0.798.
    /// </remarks>
    public sealed class StepanekDrag : IDragModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static StepanekDrag Instance { get; } = new StepanekDrag();

        /// <inheritdoc />
        public double DragCoefficient(in AeroConditions conditions) => Evaluate(conditions.SpinParameter);

        /// <summary>C_D at spin parameter <paramref name="spinParameter"/> (S &lt;= 0 gives the no-spin value 0.508).</summary>
        /// <param name="spinParameter">S = r|w|/s.</param>
        public static double Evaluate(double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0.508;
            }

            // (1/S)^2.5 = u^2 sqrt(u) with u = 1/S: a square root instead of a second Math.Pow (Pow dominated the
            // model's cost, docs/performance.md). It overflows to +inf for tiny S; inf^-0.4 is 0, the correct limit.
            double u = 1.0 / spinParameter;
            return 0.508 + PortableMath.Pow(22.053 + 4.196 * (u * u * Math.Sqrt(u)), -0.4);
        }

        /// <inheritdoc />
        public override string ToString() => "StepanekDrag";
    }

    /// <summary>
    /// Stepanek's spin-dependent tennis lift, C_L = 1/(2.022 + 0.981/S_perp), with S_perp = r|w x v_hat|/s.
    /// </summary>
    /// <remarks>
    /// Source: Stepanek (1988), Am. J. Phys. 56:138, as used by Klvana (1998) and Cross. C_L is 0 at S_perp = 0
    /// and tends to 1/2.022 = 0.495 as S_perp grows.
    /// </remarks>
    public sealed class StepanekLift : ILiftModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static StepanekLift Instance { get; } = new StepanekLift();

        /// <inheritdoc />
        public double LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter);

        /// <summary>C_L at transverse spin parameter <paramref name="spinParameter"/> (0 for S &lt;= 0).</summary>
        /// <param name="spinParameter">S_perp = r|w x v_hat|/s.</param>
        public static double Evaluate(double spinParameter)
        {
            if (!(spinParameter > 0))
            {
                return 0;
            }

            return spinParameter / (2.022 * spinParameter + 0.981);
        }

        /// <inheritdoc />
        public override string ToString() => "StepanekLift";
    }
}
