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

        /// <summary>The Euclidean length.</summary>
        public double Length
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => Math.Sqrt(X * X + Y * Y + Z * Z);
        }

        /// <summary>The squared Euclidean length (no square root).</summary>
        public double LengthSquared
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => X * X + Y * Y + Z * Z;
        }

        /// <summary>True when all three components are finite (neither NaN nor infinite).</summary>
        public bool IsFinite => IsFiniteNumber(X) && IsFiniteNumber(Y) && IsFiniteNumber(Z);

        /// <summary>
        /// The unit vector in this direction, or <see cref="Zero"/> for the zero vector or a vector with a
        /// non-finite component (never NaN). Finite vectors too long for their squared length to fit in a
        /// double (components above about 1.3e154) are scaled down first, so they still give a unit vector.
        /// </summary>
        public Vector3d NormalizedOrZero()
        {
            double length = Length;
            if (length > 0 && length <= double.MaxValue)
            {
                return this / length;
            }

            if (!(length > 0) || !IsFinite)
            {
                return Zero;
            }

            // |v|^2 overflowed although every component is finite: divide by the largest component first.
            double largest = Math.Max(Math.Abs(X), Math.Max(Math.Abs(Y), Math.Abs(Z)));
            var scaled = new Vector3d(X / largest, Y / largest, Z / largest);
            return scaled / scaled.Length;
        }

        /// <summary>The dot product <paramref name="a"/> . <paramref name="b"/>.</summary>
        /// <param name="a">Left operand.</param>
        /// <param name="b">Right operand.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(in Vector3d a, in Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>The cross product <paramref name="a"/> x <paramref name="b"/> (standard determinant formula).</summary>
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
        public static double Distance(in Vector3d a, in Vector3d b) => (a - b).Length;

        /// <summary>Linear interpolation a + (b - a) t.</summary>
        /// <param name="a">Value at t = 0.</param>
        /// <param name="b">Value at t = 1.</param>
        /// <param name="t">Interpolation parameter (not clamped).</param>
        public static Vector3d Lerp(in Vector3d a, in Vector3d b, double t) => a + (b - a) * t;

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
