using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// A modern golf ball's drag and lift for the whole flight, built only from measured coefficients: Naruo, Mizota &amp;
    /// Shimozono's (2004) wind-tunnel polynomials in the spin ratio, carried to other Reynolds numbers by the Re terms of
    /// the USGA indoor-test-range model (US patent 6,186,002). No constant is fitted to a flight.
    /// </summary>
    /// <remarks>
    /// <para>With S held in [0, 1.13] (Naruo's range; beyond it the law keeps its value at 1.13) and r = Re / 1e5 held
    /// in [0.81, 2.0] (the USGA model's range):</para>
    /// <para>C_D = P_D(S) + 0.0165 (r - 1), P_D(S) = 0.7510 S^4 - 1.760 S^3 + 1.098 S^2 + 0.2148 S + 0.2049;</para>
    /// <para>C_L = min(1, S_perp / 0.03) max(0, P_L(S_perp) - 0.0122 (1/r^2 - 1)),
    /// P_L(S) = -0.2158 S^4 + 1.006 S^3 - 1.644 S^2 + 1.250 S + 0.0616.</para>
    /// <para>Naruo et al. (Trans. JSME B 70(697):2371, 2004) measured S 0.03-1.13 at Re 7.09e4-1.25e5 and found no
    /// Reynolds-number dependence there; their polynomials stand for Re 1e5 (the middle of that range). The USGA model
    /// (fitted to launched balls, Re 0.81e5-2.0e5, SR 0.044-0.218) gives the Re dependence: C_D rises by 0.0165 per 1e5,
    /// C_L falls as -0.0122 / r^2; only those two terms are used, relative to r = 1. Below S 0.03 the lift ramps linearly to
    /// 0 at S = 0 (no spin, no lift; P_L(0) = 0.0616 is the polynomial's intercept, outside the measured range). The
    /// coefficients were read second-hand (quoted in published notes; the paper and the patent's equations were not read
    /// here); data/coefficients/README.md lists them with the launched-ball and wind-tunnel points the law is checked
    /// against (test <c>GolfNaruoUsgaLawTests</c>).</para>
    /// <para>Not modelled: the negative lift (reverse Magnus effect) Lyu et al. (2020) measured at Re 5e4-7e4 and S
    /// 0.09-0.15. Continuous in S and Re, bounded (0.20 &lt;= C_D &lt;= 0.56, 0 &lt;= C_L &lt;= 0.49 for every input,
    /// including S = infinity, Re = 0 and NaN), immutable, allocation-free.</para>
    /// </remarks>
    internal sealed class GolfNaruoUsgaLaw : IDragModel, ILiftModel
    {
        /// <summary>The top of Naruo et al.'s spin-ratio range; the law holds its value beyond it.</summary>
        internal const double MaxSpinRatio = 1.13;

        /// <summary>Below this spin ratio (Naruo's lowest) the lift ramps linearly to 0 at S = 0.</summary>
        internal const double LiftRampSpinRatio = 0.03;

        /// <summary>The USGA model's Reynolds-number range, in units of 1e5; r is held inside it.</summary>
        internal const double MinReynolds = 0.81, MaxReynolds = 2.0;

        /// <summary>A bound on C_D for every input: P_D(1.13) + 0.0165 = 0.551.</summary>
        internal const double DragBound = 0.56;

        /// <summary>A bound on C_L for every input: P_L(1.13) + 0.0122 (1 - 1/4) = 0.484.</summary>
        internal const double LiftBound = 0.49;

        private GolfNaruoUsgaLaw()
        {
        }

        /// <summary>The law (it has no parameters).</summary>
        internal static GolfNaruoUsgaLaw Instance { get; } = new GolfNaruoUsgaLaw();

        /// <summary>Naruo et al.'s C_D polynomial at <paramref name="s"/> (no clamp).</summary>
        internal static double NaruoDrag(double s) => (((0.7510 * s - 1.760) * s + 1.098) * s + 0.2148) * s + 0.2049;

        /// <summary>Naruo et al.'s C_L polynomial at <paramref name="s"/> (no clamp).</summary>
        internal static double NaruoLift(double s) => (((-0.2158 * s + 1.006) * s - 1.644) * s + 1.250) * s + 0.0616;

        private static double SpinRatio(double s) => s > 0 ? Math.Min(s, MaxSpinRatio) : 0.0; // NaN and negatives count as 0

        private static double Reynolds(double re) => re > MinReynolds * 1e5 ? Math.Min(re / 1e5, MaxReynolds) : MinReynolds; // NaN: the low end

        /// <summary>C_D at spin ratio <paramref name="spinParameter"/> and Reynolds number <paramref name="reynoldsNumber"/>.</summary>
        internal static double Drag(double spinParameter, double reynoldsNumber) =>
            NaruoDrag(SpinRatio(spinParameter)) + 0.0165 * (Reynolds(reynoldsNumber) - 1.0);

        /// <summary>C_L at transverse spin ratio <paramref name="spinParameter"/> and Reynolds number <paramref name="reynoldsNumber"/>.</summary>
        internal static double Lift(double spinParameter, double reynoldsNumber)
        {
            double s = SpinRatio(spinParameter);
            double r = Reynolds(reynoldsNumber);
            double polynomial = NaruoLift(s) - 0.0122 * (1.0 / (r * r) - 1.0);
            return Math.Min(1.0, s / LiftRampSpinRatio) * Math.Max(0.0, polynomial);
        }

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) => Drag(conditions.SpinParameter, conditions.ReynoldsNumber);

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Lift(conditions.TransverseSpinParameter, conditions.ReynoldsNumber);

        /// <inheritdoc />
        public override string ToString() => "GolfNaruoUsgaLaw(Naruo et al. 2004 polynomials in S, USGA US 6,186,002 Re terms)";
    }
}
