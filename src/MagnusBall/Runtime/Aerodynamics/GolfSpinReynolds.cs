using System;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// Golf-ball drag that rises with spin and has a drag crisis in the Reynolds number:
    /// C_D = a + b S + c / (1 + exp((Re - Re_c) / w)), with S = r|w|/s and Re = rho s 2r / mu.
    /// </summary>
    /// <remarks>
    /// <para>The form follows the wind-tunnel picture of a dimpled ball (Bearman &amp; Harvey 1976, Aeronautical
    /// Quarterly 27:112, Figs. 7 and 8): drag grows about linearly with the spin parameter at every speed, and
    /// rises by a few hundredths below a critical Reynolds number (the "drag crisis" of a dimpled ball lies near
    /// Re 1e5, inside a golf shot's speed range). The logistic makes the crisis smooth; C_D tends to a + b S above
    /// it and to a + c + b S below it.</para>
    /// <para><see cref="BearmanHarvey"/> holds the five constants fitted here to Bearman &amp; Harvey's 210 grid
    /// points (data/coefficients/bearman-harvey-1976-golf.csv); <see cref="TrackManCalibrated"/> the set the
    /// <c>golf</c> preset flies, with the floor a refitted once to 24 TrackMan shots (docs/presets.md).
    /// Immutable, allocation-free; the formula is in <see cref="Evaluate"/>.</para>
    /// </remarks>
    public sealed class GolfSpinReynoldsDrag : IDragModel, ISpinLinearDrag
    {
        /// <summary>Creates the law.</summary>
        /// <param name="floor">a, C_D above the crisis at zero spin; finite, &gt;= 0.</param>
        /// <param name="spinSlope">b, the rise of C_D per unit spin parameter; finite, &gt;= 0.</param>
        /// <param name="crisisRise">c, how much higher C_D is far below the crisis; finite, &gt;= 0.</param>
        /// <param name="crisisReynolds">Re_c, the crisis' middle; finite, &gt; 0.</param>
        /// <param name="crisisWidth">w, its width in Reynolds number; finite, &gt; 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is out of range; the message names it.</exception>
        public GolfSpinReynoldsDrag(double floor, double spinSlope, double crisisRise, double crisisReynolds, double crisisWidth)
        {
            Floor = Require.NonNegative(floor, nameof(floor));
            SpinSlope = Require.NonNegative(spinSlope, nameof(spinSlope));
            CrisisRise = Require.NonNegative(crisisRise, nameof(crisisRise));
            CrisisReynolds = Require.Positive(crisisReynolds, nameof(crisisReynolds));
            CrisisWidth = Require.Positive(crisisWidth, nameof(crisisWidth));
        }

        /// <summary>a, C_D above the crisis at zero spin.</summary>
        internal double Floor { get; }

        /// <summary>b, the rise of C_D per unit spin parameter.</summary>
        internal double SpinSlope { get; }

        /// <summary>c, the extra drag far below the crisis.</summary>
        internal double CrisisRise { get; }

        /// <summary>Re_c, the Reynolds number in the middle of the crisis.</summary>
        internal double CrisisReynolds { get; }

        /// <summary>w, the crisis' width in Reynolds number.</summary>
        internal double CrisisWidth { get; }

        /// <summary>
        /// Fitted here (least squares, all 210 points) to Bearman &amp; Harvey's (1976) wind-tunnel grid for a
        /// hexagonally dimpled ball, 13.7-88.1 m/s and 2000-6000 rpm, as transcribed in
        /// data/coefficients/bearman-harvey-1976-golf.csv: a 0.2301, b 0.2839, c 0.0399, Re_c 97 237, w 10 160.
        /// Residuals: rms 0.007 for speeds of 29.9 m/s and above (Re &gt;= 8.2e4), rms 0.018 below, largest 0.043.
        /// </summary>
        public static GolfSpinReynoldsDrag BearmanHarvey { get; } = new GolfSpinReynoldsDrag(0.2301, 0.2839, 0.0399, 97237, 10160);

        /// <summary>
        /// The <c>golf</c> preset's drag: <see cref="BearmanHarvey"/> with one constant, the floor a, refitted once
        /// to all 24 shots of data/published/golf-trackman-session.json (0.2301 -> 0.2240; docs/presets.md, "Golf:
        /// the calibration"). The other four constants are Bearman &amp; Harvey's.
        /// </summary>
        public static GolfSpinReynoldsDrag TrackManCalibrated { get; } = new GolfSpinReynoldsDrag(0.2240, 0.2839, 0.0399, 97237, 10160);

        /// <inheritdoc />
        double IDragModel.DragCoefficient(in AeroConditions conditions) => Evaluate(conditions.SpinParameter, conditions.ReynoldsNumber);

        /// <summary>C_D at spin parameter <paramref name="spinParameter"/> and Reynolds number <paramref name="reynoldsNumber"/>.</summary>
        /// <param name="spinParameter">S = r|w|/s (negative or NaN counts as 0).</param>
        /// <param name="reynoldsNumber">Re = rho s 2r / mu (&gt;= 0).</param>
        internal double Evaluate(double spinParameter, double reynoldsNumber)
        {
            double s = spinParameter > 0 ? spinParameter : 0.0;
            // exp overflows to +inf far above the crisis, where c/inf = 0 is the right limit; no NaN for Re >= 0.
            return Floor + Overflow.Multiply(SpinSlope, s) + CrisisRise / (1.0 + PortableMath.Exp((reynoldsNumber - CrisisReynolds) / CrisisWidth));
        }

        double ISpinLinearDrag.SpinSlope => SpinSlope;

        double ISpinLinearDrag.CoefficientWithoutSpin(in AeroConditions conditions) =>
            Floor + CrisisRise / (1.0 + PortableMath.Exp((conditions.ReynoldsNumber - CrisisReynolds) / CrisisWidth));

        /// <inheritdoc />
        public override string ToString() =>
            $"GolfSpinReynoldsDrag({Floor:R} + {SpinSlope:R} S + {CrisisRise:R}/(1 + exp((Re - {CrisisReynolds:R})/{CrisisWidth:R})))";
    }

    /// <summary>
    /// Golf-ball lift that rises steeply at small spin, flattens at large spin and weakens with the Reynolds number:
    /// C_L = m S^p (1e5/Re)^q / (1 + exp(-(Re - Re_o)/w_o)), with S = S_perp = r|w x v_hat|/s and 0 &lt; p &lt;= 1.
    /// </summary>
    /// <remarks>
    /// <para>Bearman &amp; Harvey's (1976) lift grid rises steeply at small spin and flattens (0.13 at S 0.05, 0.20 at
    /// 0.15, 0.37 at 0.43, 0.47 at 0.94), is a little lower at high Reynolds number for the same S, and drops at the
    /// lowest speeds where the boundary layer stays laminar (0.10 at 13.7 m/s and S 0.31). A power of S below 1 carries
    /// the steep start and the flattening (the grid's rows rise as S^0.4-0.5), the power of Re the speed dependence
    /// and the logistic the laminar onset.</para>
    /// <para>An earlier form of this law, m S/(S + h), went through the same grid with the same number of constants
    /// but could not rise steeply enough at the drivers' spin parameters (S 0.05-0.08): there it was 15-30 % below
    /// the grid (0.09-0.12 against 0.13-0.14), and drivers flew low and short. The power law follows the grid there
    /// to 0.01 (test <c>SourceDataTests.GolfBearmanHarvey_FitReproducesTheWindTunnelGrid</c>).</para>
    /// <para><see cref="BearmanHarvey"/>: fitted to the 210 grid points; the <c>golf</c> preset flies it unchanged
    /// (its calibration refits only the drag floor, <see cref="GolfSpinReynoldsDrag.TrackManCalibrated"/>).
    /// Immutable, allocation-free; the formula is in <see cref="Evaluate"/>.</para>
    /// </remarks>
    public sealed class GolfSpinReynoldsLift : ILiftModel
    {
        private const double ReferenceReynolds = 1e5;

        /// <summary>Creates the law.</summary>
        /// <param name="scale">m, C_L at S = 1 and Re = 1e5 far above the onset; finite, &gt;= 0.</param>
        /// <param name="spinExponent">p, lift grows as S^p; finite, in (0, 1] (so C_L is continuous and concave in S).</param>
        /// <param name="reynoldsExponent">q, lift scales as (1e5/Re)^q; finite, in [0, 1].</param>
        /// <param name="onsetReynolds">Re_o, the middle of the low-speed lift onset; finite, &gt;= 0.</param>
        /// <param name="onsetWidth">w_o, its width in Reynolds number; finite, &gt; 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">A value is out of range; the message names it.</exception>
        public GolfSpinReynoldsLift(double scale, double spinExponent, double reynoldsExponent, double onsetReynolds, double onsetWidth)
        {
            Scale = Require.NonNegative(scale, nameof(scale));
            if (!(spinExponent > 0 && spinExponent <= 1))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(spinExponent), spinExponent, $"spinExponent must be in (0, 1]; got {Require.Format(spinExponent)}.");
            }

            SpinExponent = spinExponent;
            ReynoldsExponent = Require.InRange(reynoldsExponent, 0, 1, nameof(reynoldsExponent));
            OnsetReynolds = Require.NonNegative(onsetReynolds, nameof(onsetReynolds));
            OnsetWidth = Require.Positive(onsetWidth, nameof(onsetWidth));
        }

        /// <summary>m, the lift at S = 1 and Re = 1e5 (far above the onset).</summary>
        internal double Scale { get; }

        /// <summary>p, the exponent of the spin parameter.</summary>
        internal double SpinExponent { get; }

        /// <summary>q, the Reynolds-number exponent.</summary>
        internal double ReynoldsExponent { get; }

        /// <summary>Re_o, the middle of the low-speed onset.</summary>
        internal double OnsetReynolds { get; }

        /// <summary>w_o, the onset's width.</summary>
        internal double OnsetWidth { get; }

        /// <summary>
        /// Fitted here (least squares, all 210 points, equal weights) to Bearman &amp; Harvey's (1976) lift grid
        /// (data/coefficients/bearman-harvey-1976-golf.csv): m 0.5959, p 0.4882, q 0.2097, Re_o 26 160, w_o 19 420.
        /// Residuals: rms 0.008 for speeds of 29.9 m/s and above (largest 0.029), 0.036 below, largest 0.17
        /// (13.7 m/s, 2000 rpm, the most laminar point).
        /// </summary>
        public static GolfSpinReynoldsLift BearmanHarvey { get; } = new GolfSpinReynoldsLift(0.5959, 0.4882, 0.2097, 26160, 19420);

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter, conditions.ReynoldsNumber);

        /// <summary>C_L at transverse spin parameter <paramref name="spinParameter"/> and Reynolds number <paramref name="reynoldsNumber"/>.</summary>
        /// <param name="spinParameter">S_perp (0 or less, or NaN, gives 0).</param>
        /// <param name="reynoldsNumber">Re (0 or less gives 0: no flow, no lift).</param>
        internal double Evaluate(double spinParameter, double reynoldsNumber)
        {
            if (!(spinParameter > 0) || !(reynoldsNumber > 0))
            {
                return 0.0;
            }

            // S is +infinity when |w| r / s overflows (a finite spin at a vanishing speed): the law is taken at the largest
            // finite S there (the power has no finite limit; this keeps C_L finite, so the model stays free of NaN).
            double spin = Scale * PortableMath.Pow(double.IsPositiveInfinity(spinParameter) ? double.MaxValue : spinParameter, SpinExponent);
            // Re is held at 1 or more inside the power so a near-zero speed cannot make it overflow (q <= 1).
            double reynolds = PortableMath.Pow(ReferenceReynolds / Math.Max(reynoldsNumber, 1.0), ReynoldsExponent);
            double onset = 1.0 / (1.0 + PortableMath.Exp(-(reynoldsNumber - OnsetReynolds) / OnsetWidth));
            return spin * reynolds * onset;
        }

        /// <inheritdoc />
        public override string ToString() =>
            $"GolfSpinReynoldsLift({Scale:R} S^{SpinExponent:R} (1e5/Re)^{ReynoldsExponent:R}, onset {OnsetReynolds:R}/{OnsetWidth:R})";
    }
}
