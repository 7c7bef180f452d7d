using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Soccer-ball drag after Goff &amp; Carre: a smooth drag crisis for a non-spinning ball and a power law
    /// in the spin parameter for a spinning one; C_D = max(C_D,crisis(s), C_D,spin(S)).
    /// </summary>
    /// <remarks>
    /// <para>Non-spinning ball (Goff &amp; Carre 2010, "Soccer ball lift coefficients via trajectory analysis",
    /// Eur. J. Phys. 31:775; secondary transcription): C_D = 0.155 + 0.346 / (1 + exp((s - 12.19) / 1.309)),
    /// with s the air-relative speed in m/s: about 0.50 below 8 m/s, 0.155 above 18 m/s, halfway at 12.19 m/s.
    /// It is a logistic curve, so the drag crisis is continuous and smooth (the source fit has no jump).</para>
    /// <para>Spinning ball (Goff &amp; Carre 2009, Am. J. Phys. 77:1020; secondary): C_D = 0.4127 S^0.3056 with
    /// S = r|w|/s.</para>
    /// <para>How the two are combined is an assumption made here, not a published rule: the larger of the
    /// two. The spin law tends to 0 as S -> 0, where it cannot describe a non-spinning ball, and spin is
    /// observed to raise drag above the supercritical 0.155, not below the subcritical 0.5. The maximum of two
    /// continuous functions is continuous (it has a kink where they cross).</para>
    /// </remarks>
    public sealed class GoffCarreSoccerDrag : IDragModel
    {
        /// <summary>The shared instance (the law has no parameters).</summary>
        public static GoffCarreSoccerDrag Instance { get; } = new GoffCarreSoccerDrag();

        /// <summary>
        /// Creates the law. It holds no state, so every instance gives the same numbers as <see cref="Instance"/>
        /// (which the presets and the flight kernel use; the kernel specialises on the type, not the instance).
        /// </summary>
        internal GoffCarreSoccerDrag()
        {
        }

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) => Evaluate(conditions.Speed, conditions.SpinParameter);

        /// <summary>C_D at air-relative speed <paramref name="speed"/> and spin parameter <paramref name="spinParameter"/>.</summary>
        /// <param name="speed">Air-relative speed s, m/s.</param>
        /// <param name="spinParameter">S = r|w|/s.</param>
        internal static double Evaluate(double speed, double spinParameter) =>
            Math.Max(NonSpinning(speed), Spinning(spinParameter));

        /// <summary>The non-spinning drag crisis, 0.155 + 0.346 / (1 + exp((s - 12.19) / 1.309)).</summary>
        /// <param name="speed">Air-relative speed s, m/s.</param>
        internal static double NonSpinning(double speed)
        {
            // exp overflows to +inf only far above the crisis (s > about 940 m/s), where 0.346/inf = 0 gives the
            // correct supercritical limit 0.155; at s = 0 it is exp(-12.19/1.309) = 9e-5. No NaN for any s >= 0.
            return 0.155 + 0.346 / (1.0 + PortableMath.Exp((speed - 12.19) / 1.309));
        }

        /// <summary>The spinning-ball law 0.4127 S^0.3056 (0 for S &lt;= 0).</summary>
        /// <param name="spinParameter">S = r|w|/s.</param>
        internal static double Spinning(double spinParameter) =>
            spinParameter > 0 ? 0.4127 * PortableMath.Pow(spinParameter, 0.3056) : 0.0;

        /// <inheritdoc />
        public override string ToString() => "GoffCarreSoccerDrag";
    }
}
