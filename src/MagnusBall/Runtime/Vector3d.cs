using System;
using System.Globalization;
using System.Runtime.CompilerServices;

namespace MagnusBall
{
    /// <summary>
    /// A three-component double-precision vector: positions (m), velocities (m/s), accelerations (m/s^2),
    /// angular velocities (rad/s) and forces. The library knows no "up": every component is treated alike.
    /// </summary>
    /// <remarks>
    /// The cross product is the standard determinant formula in whatever frame the numbers live in, so
    /// <c>w x v</c> keeps its physical meaning in right-handed frames (z-up, Godot's y-up) and in Unity's
    /// left-handed y-up frame, as long as the angular velocity is expressed in that frame's own rotation
    /// convention (see docs/physics.md, "Frames and handedness").
    /// </remarks>
    public readonly struct Vector3d : IEquatable<Vector3d>
    {
        /// <summary>The first component.</summary>
        public readonly double X;

        /// <summary>The second component.</summary>
        public readonly double Y;

        /// <summary>The third component.</summary>
        public readonly double Z;

        /// <summary>Creates a vector from its three components.</summary>
        /// <param name="x">First component.</param>
        /// <param name="y">Second component.</param>
        /// <param name="z">Third component.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3d(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>The zero vector.</summary>
        public static Vector3d Zero => default;

        /// <summary>The unit vector (1, 0, 0).</summary>
        public static Vector3d UnitX => new Vector3d(1, 0, 0);

        /// <summary>The unit vector (0, 1, 0).</summary>
        public static Vector3d UnitY => new Vector3d(0, 1, 0);

        /// <summary>The unit vector (0, 0, 1).</summary>
        public static Vector3d UnitZ => new Vector3d(0, 0, 1);

        /// <summary>
        /// The Euclidean length. Finite for every finite vector whose length fits in a double: components too large
        /// for their squares (above about 1.3e154) or too small (below about 1.5e-154) are scaled first, so
        /// (1e155, 0, 0) has length 1e155, not infinity, and (1e-160, 0, 0) has 1e-160, not 0.
        /// </summary>
        public double Length
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => LengthOf(X, Y, Z);
        }

        /// <summary><see cref="Length"/> of (x, y, z), from the components (for code that keeps them in separate locals).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double LengthOf(double x, double y, double z)
        {
            double squared = x * x + y * y + z * z;
            // The common case: no overflow and no loss to subnormals (2.2250738585072014e-308 is the smallest normal double).
            return squared >= 2.2250738585072014e-308 && squared <= double.MaxValue ? Math.Sqrt(squared) : ScaledLength(x, y, z, squared);
        }

        /// <summary>The squared Euclidean length (no square root).</summary>
        public double LengthSquared
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => X * X + Y * Y + Z * Z;
        }

        /// <summary>True when all three components are finite (neither NaN nor infinite).</summary>
        public bool IsFinite
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)] // Mono inlines only tiny methods without it: the flight core tests six per step
            get => IsFiniteNumber(X) && IsFiniteNumber(Y) && IsFiniteNumber(Z);
        }

        /// <summary>
        /// The unit vector in this direction, or <see cref="Zero"/> for the zero vector or a vector with a
        /// non-finite component (never NaN). Every other finite vector gives a unit vector, however long or short:
        /// components beyond the range of their squares are scaled by the largest one first.
        /// </summary>
        public Vector3d NormalizedOrZero()
        {
            double squared = X * X + Y * Y + Z * Z;
            if (squared >= 2.2250738585072014e-308 && squared <= double.MaxValue)
            {
                return this / Math.Sqrt(squared);
            }

            if (!IsFinite)
            {
                return Zero;
            }

            double largest = Math.Max(Math.Abs(X), Math.Max(Math.Abs(Y), Math.Abs(Z)));
            if (largest == 0)
            {
                return Zero;
            }

            // Divide (not multiply by 1/largest, which overflows for a subnormal largest) so the components are in [-1, 1].
            var scaled = new Vector3d(X / largest, Y / largest, Z / largest);
            return scaled / Math.Sqrt(scaled.X * scaled.X + scaled.Y * scaled.Y + scaled.Z * scaled.Z);
        }

        /// <summary>The largest absolute component (0 for the zero vector).</summary>
        internal double MaxAbsComponent => Math.Max(Math.Abs(X), Math.Max(Math.Abs(Y), Math.Abs(Z)));

        // Static, with the components by value: an instance method here would take the vector's address, and a vector whose
        // address is taken lives in memory (the JIT keeps every local whose Length is read on the stack, a store and a
        // reload on the flight kernel's critical path).
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double ScaledLength(double x, double y, double z, double squared)
        {
            if (!(IsFiniteNumber(x) && IsFiniteNumber(y) && IsFiniteNumber(z)))
            {
                return Math.Sqrt(squared); // NaN or infinity, as the plain formula gives
            }

            double largest = Math.Max(Math.Abs(x), Math.Max(Math.Abs(y), Math.Abs(z)));
            if (largest == 0)
            {
                return 0;
            }

            x /= largest;
            y /= largest;
            z /= largest;
            return largest * Math.Sqrt(x * x + y * y + z * z); // infinity only if the length itself exceeds double.MaxValue
        }

        /// <summary>
        /// The dot product <paramref name="a"/> . <paramref name="b"/>: the plain formula, for speed (it is inlined into the
        /// library's hot paths). Where a product of components exceeds double.MaxValue (components beyond about 1.3e154)
        /// it is infinite, and two such of opposite signs give NaN; <see cref="Length"/> and the library's own distances
        /// to planes are formed without that overflow.
        /// </summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(in Vector3d a, in Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>
        /// (<paramref name="a"/> - <paramref name="b"/>) . <paramref name="unit"/> for a unit (or shorter) vector: the plain
        /// formula, and where that is not finite (a and b near 1e308 apart: a component of the difference overflowed, then
        /// inf * 0 or inf - inf), 4 times the same formed from quarters, which cannot overflow for finite input (the
        /// reasoning at <see cref="QuarterDotOfDifference"/>): infinite only where the true value exceeds a double, NaN only
        /// for a non-finite input. The common case is the plain formula, bit for bit.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DotOfDifference(in Vector3d a, in Vector3d b, in Vector3d unit)
        {
            double d = PlainDotOfDifference(a, b, unit);
            return IsFiniteNumber(d) ? d : 4 * QuarterDotOfDifference(a, b, unit);
        }

        // (a - b) . n by the plain formula, Dot(a - b, n) operation for operation, without the difference vector (Mono zeroes
        // and copies such a temporary through memory); not finite where a component of a - b or a partial sum overflows.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double PlainDotOfDifference(in Vector3d a, in Vector3d b, in Vector3d n) =>
            (a.X - b.X) * n.X + (a.Y - b.Y) * n.Y + (a.Z - b.Z) * n.Z;

        // A quarter of (a - b) . n, never overflowing for finite input, for where the plain formula was not finite: a
        // component of a - b overflowed (its product infinite where the true one may be finite, NaN beside a zero component
        // of n, inf * 0, or two such products cancelling, inf - inf), or a partial sum of the products did. Each
        // quarter-difference is at most double.MaxValue / 2, so the three products sum to at most sqrt(3) / 2 of it (n of
        // length 1 or less): no partial sum overflows (halves did: 1.7e308 (0.55 + 0.55) overflows before -1.7e308 0.63 is
        // added, for a true value of 1.6e308). Quartering is exact but for subnormals (an absolute error of a few times
        // 4.9e-324). NaN only for a NaN input.
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static double QuarterDotOfDifference(in Vector3d a, in Vector3d b, in Vector3d n) =>
            (0.25 * a.X - 0.25 * b.X) * n.X + (0.25 * a.Y - 0.25 * b.Y) * n.Y + (0.25 * a.Z - 0.25 * b.Z) * n.Z;

        /// <summary>
        /// The cross product <paramref name="a"/> x <paramref name="b"/> (standard determinant formula, for speed): a
        /// component whose two products exceed double.MaxValue with the same sign (components beyond about 1.3e154) is NaN.
        /// </summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d Cross(in Vector3d a, in Vector3d b) => new Vector3d(
            a.Y * b.Z - a.Z * b.Y,
            a.Z * b.X - a.X * b.Z,
            a.X * b.Y - a.Y * b.X);

        /// <summary>The distance between two points.</summary>
        /// <param name="a">First point.</param>
        /// <param name="b">Second point.</param>
        internal static double Distance(in Vector3d a, in Vector3d b) => (a - b).Length;

        /// <summary>Linear interpolation a + (b - a) t.</summary>
        /// <param name="a">Value at t = 0.</param>
        /// <param name="b">Value at t = 1.</param>
        /// <param name="t">Interpolation parameter (not clamped).</param>
        internal static Vector3d Lerp(in Vector3d a, in Vector3d b, double t) => a + (b - a) * t;

        /// <summary>Component-wise sum.</summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator +(in Vector3d a, in Vector3d b) => new Vector3d(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        /// <summary>Component-wise difference.</summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator -(in Vector3d a, in Vector3d b) => new Vector3d(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        /// <summary>Negation.</summary>
        /// <param name="a">Operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator -(in Vector3d a) => new Vector3d(-a.X, -a.Y, -a.Z);

        /// <summary>Scaling by a number.</summary>
        /// <param name="a">Vector.</param>
        /// <param name="s">Factor.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator *(in Vector3d a, double s) => new Vector3d(a.X * s, a.Y * s, a.Z * s);

        /// <summary>Scaling by a number.</summary>
        /// <param name="s">Factor.</param>
        /// <param name="a">Vector.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator *(double s, in Vector3d a) => new Vector3d(a.X * s, a.Y * s, a.Z * s);

        /// <summary>Division by a number.</summary>
        /// <param name="a">Vector.</param>
        /// <param name="s">Divisor.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3d operator /(in Vector3d a, double s)
        {
            double inverse = 1.0 / s;
            return new Vector3d(a.X * inverse, a.Y * inverse, a.Z * inverse);
        }

        /// <summary>Exact component-wise equality.</summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        public static bool operator ==(in Vector3d a, in Vector3d b) => a.Equals(b);

        /// <summary>Exact component-wise inequality.</summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        public static bool operator !=(in Vector3d a, in Vector3d b) => !a.Equals(b);

        /// <inheritdoc />
        public bool Equals(Vector3d other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);

        /// <inheritdoc />
        public override bool Equals(object? obj) => obj is Vector3d other && Equals(other);

        /// <inheritdoc />
        public override int GetHashCode() => HashCode.Combine(X, Y, Z);

        /// <summary>Formats as "(x, y, z)" with invariant culture and round-trip precision.</summary>
        public override string ToString() => string.Format(CultureInfo.InvariantCulture, "({0:R}, {1:R}, {2:R})", X, Y, Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool IsFiniteNumber(double value) => double.IsFinite(value);
    }
}
