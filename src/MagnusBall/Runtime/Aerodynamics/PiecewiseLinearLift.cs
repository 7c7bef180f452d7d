using System;
using System.Collections.Generic;

namespace MagnusBall.Aerodynamics
{
    /// <summary>
    /// A tabulated lift law: C_L as a function of the transverse spin parameter S_perp = r|w x v_hat|/s,
    /// interpolated linearly between the points and held constant beyond the first and last point.
    /// Continuous everywhere (piecewise linear, no jumps); allocates nothing when evaluated.
    /// </summary>
    /// <remarks>
    /// Holding the end value, rather than extending the last segment, is a deliberate choice: it keeps C_L
    /// bounded where the source has no data (spin parameters seen late in a slow, high-spin flight), instead
    /// of letting a straight line run on. Two published tables are provided as <see cref="SoccerGoffCarre"/>
    /// and <see cref="GolfSmitsSmith"/>.
    /// </remarks>
    public sealed class PiecewiseLinearLift : ILiftModel
    {
        private readonly double[] _s;
        private readonly double[] _c;
        private readonly IReadOnlyList<double> _sView;
        private readonly IReadOnlyList<double> _cView;

        /// <summary>Creates the table (the arrays are copied).</summary>
        /// <param name="spinParameters">S_perp values: at least one, finite, &gt;= 0, strictly increasing.</param>
        /// <param name="liftCoefficients">C_L at each S_perp: finite, as many as spinParameters.</param>
        /// <exception cref="ArgumentException">The table is empty, its lengths differ, or a value is out of range.</exception>
        public PiecewiseLinearLift(IReadOnlyList<double> spinParameters, IReadOnlyList<double> liftCoefficients)
        {
            Require.NotNull(spinParameters, nameof(spinParameters));
            Require.NotNull(liftCoefficients, nameof(liftCoefficients));
            if (spinParameters.Count == 0 || spinParameters.Count != liftCoefficients.Count)
            {
                throw new ArgumentException(
                    $"spinParameters and liftCoefficients must be non-empty and of equal length; got {spinParameters.Count} and {liftCoefficients.Count}.",
                    nameof(spinParameters));
            }

            _s = CopyOf(spinParameters);
            _c = CopyOf(liftCoefficients);
            for (int i = 0; i < _s.Length; i++)
            {
                Require.NonNegative(_s[i], nameof(spinParameters));
                Require.Finite(_c[i], nameof(liftCoefficients));
                if (i > 0 && !(_s[i] > _s[i - 1]))
                {
                    throw new ArgumentException(
                        $"spinParameters must be strictly increasing; got {Require.Format(_s[i])} after {Require.Format(_s[i - 1])}.",
                        nameof(spinParameters));
                }
            }

            _sView = Array.AsReadOnly(_s);
            _cView = Array.AsReadOnly(_c);
        }

        /// <summary>
        /// A copy. An array (what callers and the presets pass) is cloned, not read through its IReadOnlyList indexer:
        /// Mono 6.8 run with -O=-intrins (the determinism check, docs/determinism.md) overflows its stack in the
        /// interface indexer of a double[].
        /// </summary>
        private static double[] CopyOf(IReadOnlyList<double> values)
        {
            if (values is double[] array)
            {
                return (double[])array.Clone();
            }

            var copy = new double[values.Count];
            for (int i = 0; i < copy.Length; i++)
            {
                copy[i] = values[i];
            }

            return copy;
        }

        /// <summary>The table's S_perp values, increasing.</summary>
        internal IReadOnlyList<double> SpinParameters => _sView;

        /// <summary>The table's C_L values.</summary>
        internal IReadOnlyList<double> LiftCoefficients => _cView;

        /// <summary>
        /// Soccer (Goff &amp; Carre; secondary transcription): (0, 0) assumed here (no spin, no lift), the Adidas
        /// Teamgeist points S 0.05/0.11/0.16/0.20/0.27 -> C_L 0.05/0.22/0.24/0.29/0.29 (Goff &amp; Carre 2010, Eur. J.
        /// Phys. 31:775: lift extracted from filmed machine launches with wind-tunnel drag, i.e. trajectory analysis,
        /// not a wind-tunnel lift measurement) and the trajectory-analysis points S 0.49 -> 0.285, 0.71 -> 0.31 (Goff
        /// &amp; Carre 2009, Am. J. Phys. 77:1020). Held at 0.31 beyond S = 0.71. The two sources meet with a slight
        /// dip (0.29 to 0.285), kept as published.
        /// </summary>
        public static PiecewiseLinearLift SoccerGoffCarre { get; } = new PiecewiseLinearLift(
            new[] { 0.0, 0.05, 0.11, 0.16, 0.20, 0.27, 0.49, 0.71 },
            new[] { 0.0, 0.05, 0.22, 0.24, 0.29, 0.29, 0.285, 0.31 });

        /// <summary>
        /// Golf (Smits &amp; Smith 1994, "A new aerodynamic model of a golf ball in flight", Science and Golf II;
        /// secondary transcription): (0, 0), (0.04, 0.10), (0.10, 0.16), (0.20, 0.23), (0.40, 0.33), held at 0.33
        /// beyond S = 0.40.
        /// </summary>
        public static PiecewiseLinearLift GolfSmitsSmith { get; } = new PiecewiseLinearLift(
            new[] { 0.0, 0.04, 0.10, 0.20, 0.40 },
            new[] { 0.0, 0.10, 0.16, 0.23, 0.33 });

        /// <inheritdoc />
        double ILiftModel.LiftCoefficient(in AeroConditions conditions) => Evaluate(conditions.TransverseSpinParameter);

        /// <summary>C_L at <paramref name="spinParameter"/> (linear inside the table, the end value outside; NaN gives the first value).</summary>
        /// <param name="spinParameter">S_perp.</param>
        internal double Evaluate(double spinParameter)
        {
            double[] s = _s;
            double[] c = _c;
            if (!(spinParameter > s[0]))
            {
                return c[0];
            }

            int last = s.Length - 1;
            if (spinParameter >= s[last])
            {
                return c[last];
            }

            // Tables are short (a handful of points): a linear scan beats a binary search here.
            int i = 1;
            while (s[i] < spinParameter)
            {
                i++;
            }

            if (s[i] == spinParameter)
            {
                return c[i]; // exactly on a point: its printed value, without rounding through t = 1
            }

            double t = (spinParameter - s[i - 1]) / (s[i] - s[i - 1]);
            double rise = c[i] - c[i - 1];
            // Coefficients near +-double.MaxValue of opposite signs overflow their difference: weight them instead.
            return double.IsFinite(rise) ? c[i - 1] + t * rise : (1 - t) * c[i - 1] + t * c[i];
        }

        /// <inheritdoc />
        public override string ToString() => $"PiecewiseLinearLift({_s.Length} points, S {_s[0]:R}..{_s[_s.Length - 1]:R})";
    }
}
