using System;

namespace MagnusBall.Queries
{
    /// <summary>A scalar function of one launch parameter for the root finders: a trial's signed margin and its solution.</summary>
    internal interface IAimMargin
    {
        /// <summary>The margin at <paramref name="x"/> (&gt;= 0: the trial does it), with the solution it stands for.</summary>
        double Evaluate(double x, out AimSolution solution);
    }

    /// <summary>
    /// The aim solver's root finding on its trials' margins: the root from a first guess by secant steps, the Illinois
    /// method inside a bracket, and Broyden's method for two launch angles at once. Every loop is capped by a constant
    /// here; a method that reaches its cap reports failure, and the solver falls back to its scan.
    /// </summary>
    internal static class AimRoots
    {
        /// <summary>The most Illinois steps of one refinement (a bracket of 180 degrees halves to 1e-8 rad in 29 bisections).</summary>
        public const int MaximumRefineSteps = 200;

        /// <summary>The most trials <see cref="TrySecant"/> flies from its first guess.</summary>
        public const int MaximumSecantSteps = 40;

        /// <summary>The most trials of <see cref="TryPolish"/>.</summary>
        public const int MaximumPolishSteps = 4;

        /// <summary>The most Broyden steps (trials) of one two-angle solve.</summary>
        public const int MaximumBroydenSteps = 24;

        /// <summary>
        /// The root of an upward crossing from a first guess <paramref name="x0"/> and an estimate of the margin's slope
        /// there (&gt; 0: the margin grows with x), by secant steps on the two latest trials, each aimed 0.4 of the
        /// tolerance past the secant's root away from the latest trial, so that once the secant is good to a small part of
        /// the tolerance two trials straddle the root within it. Once two trials bracket the root (a &lt; b,
        /// f(a) &lt; 0 &lt;= f(b)), every step stays inside the bracket, and one that did not halve it in three steps is
        /// a bisection. Returns true with the bracket's non-negative end <paramref name="root"/> (within
        /// <paramref name="tolerance"/> of the root) and its solution. False when the trials leave
        /// [<paramref name="min"/>, <paramref name="max"/>] or stop moving before a bracket, give a non-finite margin,
        /// meet a downward crossing (a margin that falls with x), or take <see cref="MaximumSecantSteps"/> trials.
        /// </summary>
        public static bool TrySecant<T>(
            ref T f, double x0, double slope, double min, double max, double maxStride, double tolerance,
            out double root, out AimSolution atRoot, out double slopeAtRoot)
            where T : struct, IAimMargin
        {
            root = double.NaN;
            atRoot = default;
            slopeAtRoot = double.NaN;
            if (!(slope > 0) || !double.IsFinite(x0))
            {
                return false;
            }

            double a = double.NaN, fa = double.NaN, b = double.NaN, fb = double.NaN;
            bool haveNegative = false, havePositive = false;
            double x = Math.Max(min, Math.Min(max, x0));
            double fx = f.Evaluate(x, out AimSolution sx);
            double xp = double.NaN, fp = double.NaN;
            double checkpoint = double.PositiveInfinity;
            int bracketedSteps = 0;
            for (int i = 0; ; i++)
            {
                if (!double.IsFinite(fx))
                {
                    return false;
                }

                if (fx < 0)
                {
                    if (havePositive && x > b)
                    {
                        return false; // short above a trial that does it: the margin falls here
                    }

                    if (!haveNegative || x > a)
                    {
                        a = x;
                        fa = fx;
                        haveNegative = true;
                    }
                }
                else
                {
                    if (haveNegative && x < a)
                    {
                        return false;
                    }

                    if (!havePositive || x < b)
                    {
                        b = x;
                        fb = fx;
                        atRoot = sx;
                        havePositive = true;
                    }
                }

                bool bracketed = haveNegative && havePositive;
                if (bracketed && b - a <= tolerance)
                {
                    root = b;
                    slopeAtRoot = (fb - fa) / (b - a);
                    return true;
                }

                if (i >= MaximumSecantSteps - 1)
                {
                    return false;
                }

                // The secant's slope on the two latest trials where it has the expected sign; else the bracket's, else the estimate.
                double s = bracketed ? (fb - fa) / (b - a) : slope;
                if (!double.IsNaN(xp) && x != xp)
                {
                    double secant = (fx - fp) / (x - xp);
                    if (secant > 0 && double.IsFinite(secant))
                    {
                        s = secant;
                    }
                }

                double dx = -fx / s;
                double next = x + dx + (fx < 0 ? 0.4 : -0.4) * tolerance;
                if (bracketed)
                {
                    // Inside the bracket (a quarter of the tolerance in from its ends); bisect when three steps did not halve it.
                    double width = b - a;
                    if (++bracketedSteps % 3 == 0)
                    {
                        if (width > 0.5 * checkpoint)
                        {
                            next = double.NaN;
                        }

                        checkpoint = width;
                    }

                    double inset = Math.Min(0.25 * width, 0.25 * tolerance);
                    next = double.IsNaN(next) || !double.IsFinite(dx) ? a + 0.5 * width : Math.Max(a + inset, Math.Min(b - inset, next));
                }
                else
                {
                    // Before a bracket: a little further past the root (a tenth of the step), within the stride and the range.
                    next += 0.1 * dx;
                    next = x + Math.Max(-maxStride, Math.Min(maxStride, next - x));
                    next = Math.Max(min, Math.Min(max, next));
                    if (next == x || !double.IsFinite(next))
                    {
                        return false; // held at a limit of the range
                    }
                }

                xp = x;
                fp = fx;
                x = next;
                fx = f.Evaluate(x, out sx);
            }
        }

        /// <summary>
        /// Moves a root found on coarse trials (<paramref name="x"/>, with the margin's slope there) onto the current trials:
        /// Newton steps with the secant's slope, each aimed 0.4 of the tolerance above the root, until a trial with
        /// f &gt;= 0 needs a correction of at most half the tolerance (it is then within the tolerance above the root, to
        /// the slope's accuracy). False when a trial leaves [<paramref name="min"/>, <paramref name="max"/>], gives a
        /// non-finite margin or <see cref="MaximumPolishSteps"/> trials do not settle (the caller then runs
        /// <see cref="TrySecant"/>).
        /// </summary>
        public static bool TryPolish<T>(
            ref T f, double x, double slope, double min, double max, double tolerance, out double root, out AimSolution atRoot)
            where T : struct, IAimMargin
        {
            root = double.NaN;
            atRoot = default;
            double xp = double.NaN, fp = double.NaN;
            for (int i = 0; i < MaximumPolishSteps; i++)
            {
                if (!(x >= min && x <= max) || !(slope > 0) || !double.IsFinite(slope))
                {
                    return false;
                }

                double fx = f.Evaluate(x, out AimSolution sx);
                if (!double.IsFinite(fx))
                {
                    return false;
                }

                double dx = -fx / slope;
                if (fx >= 0 && Math.Abs(dx) <= 0.5 * tolerance)
                {
                    root = x;
                    atRoot = sx;
                    return true;
                }

                if (!double.IsNaN(xp) && x != xp)
                {
                    double secant = (fx - fp) / (x - xp);
                    if (secant > 0 && double.IsFinite(secant))
                    {
                        slope = secant;
                        dx = -fx / slope;
                    }
                }

                xp = x;
                fp = fx;
                x += dx + 0.4 * tolerance;
            }

            return false;
        }

        /// <summary>
        /// Refines a bracket between <paramref name="a"/> (f &lt; 0) and <paramref name="b"/> (f &gt;= 0), in either
        /// order, to <paramref name="tolerance"/> by the Illinois method (regula falsi that halves the stale end's value),
        /// bisecting when a value is not finite, every third step that did not halve the bracket, or when the secant hugs
        /// an end. Returns the end where f &gt;= 0, with its solution in <paramref name="atB"/> (pass the solution at b);
        /// <paramref name="failed"/> when f returned NaN. At most <see cref="MaximumRefineSteps"/> trials.
        /// </summary>
        public static double Refine<T>(ref T f, double a, double fa, double b, double fb, ref AimSolution atB, double tolerance, out bool failed)
            where T : struct, IAimMargin
        {
            failed = false;
            int side = 0;
            double checkpoint = Math.Abs(b - a);
            bool bisect = false;
            for (int i = 0; i < MaximumRefineSteps && Math.Abs(b - a) > tolerance; i++)
            {
                double width = b - a;
                if (i % 3 == 2)
                {
                    // Safeguard: if three steps did not halve the bracket, bisect once.
                    bisect = Math.Abs(width) > 0.5 * checkpoint;
                    checkpoint = Math.Abs(width);
                }

                double t = 0.5;
                if (!bisect && double.IsFinite(fa) && double.IsFinite(fb) && fb > fa)
                {
                    // Regula falsi, kept at least a quarter of the tolerance inside the bracket.
                    double margin = Math.Min(0.25, 0.25 * tolerance / Math.Abs(width));
                    t = Math.Max(margin, Math.Min(1 - margin, -fa / (fb - fa)));
                }

                bisect = false;
                double x = a + width * t;
                double fx = f.Evaluate(x, out AimSolution sx);
                if (double.IsNaN(fx))
                {
                    failed = true;
                    return x;
                }

                if (fx >= 0)
                {
                    b = x;
                    fb = fx;
                    atB = sx;
                    if (side == 1 && double.IsFinite(fa))
                    {
                        fa *= 0.5;
                    }

                    side = 1;
                }
                else
                {
                    a = x;
                    fa = fx;
                    if (side == -1)
                    {
                        fb *= 0.5;
                    }

                    side = -1;
                }
            }

            return b;
        }
    }
}
