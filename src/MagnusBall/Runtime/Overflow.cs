using System.Runtime.CompilerServices;

namespace MagnusBall
{
    /// <summary>
    /// The physics layer's rule for numbers beyond the range of a double: a finite input never gives NaN. A value
    /// whose true magnitude fits in a double is computed (scaled before squaring where needed); one whose true
    /// magnitude exceeds double.MaxValue is +-infinity, so that a stepper sees the state diverge; and a product with
    /// a zero factor is zero (never 0 x infinity = NaN). See docs/physics.md, "Hostile input".
    /// </summary>
    internal static class Overflow
    {
        /// <summary>a b; 0 when either factor is 0 (even if the other is infinite).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double Multiply(double a, double b)
        {
            double p = a * b;
            return double.IsNaN(p) && (a == 0 || b == 0) ? 0 : p;
        }

        /// <summary>v s component by component; a zero component (or s = 0) stays 0.</summary>
        internal static Vector3d Multiply(in Vector3d v, double s)
        {
            var p = new Vector3d(v.X * s, v.Y * s, v.Z * s);
            return p.IsFinite ? p : new Vector3d(Multiply(v.X, s), Multiply(v.Y, s), Multiply(v.Z, s));
        }

        /// <summary>a + b component by component; infinities of opposite signs (an overflow both ways) give +infinity, not NaN.</summary>
        internal static Vector3d Add(in Vector3d a, in Vector3d b)
        {
            Vector3d sum = a + b;
            return sum.IsFinite ? sum : new Vector3d(Add(a.X, b.X), Add(a.Y, b.Y), Add(a.Z, b.Z));
        }

        /// <summary>a + b; infinities of opposite signs give +infinity, not NaN.</summary>
        internal static double Add(double a, double b)
        {
            double sum = a + b;
            return double.IsNaN(sum) && !double.IsNaN(a) && !double.IsNaN(b) ? double.PositiveInfinity : sum;
        }
    }
}
