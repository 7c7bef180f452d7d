using System.Runtime.CompilerServices;

namespace MagnusBall
{
    /// <summary>
    /// An oriented plane: a point on it and a unit normal. The ground, a net, a goal line or a wall.
    /// The signed distance of a point is positive on the side the normal points to.
    /// </summary>
    /// <remarks>
    /// Nothing here assumes an axis is up: the ground is the plane through a point whose normal is the
    /// frame's up direction (-gravity normalised), see <see cref="Ground(FlightModel, Vector3d)"/>. A ball "lands"
    /// when it crosses the ground against its normal; it "crosses" a net or goal plane along the normal.
    /// The default value has a zero normal (every signed distance is 0) and is never crossed.
    /// </remarks>
    public readonly struct Plane
    {
        /// <summary>A point on the plane, m.</summary>
        public readonly Vector3d Point;

        /// <summary>The unit normal; the positive side of the plane.</summary>
        public readonly Vector3d Normal;

        /// <summary>Creates the plane through <paramref name="point"/> with normal direction <paramref name="normal"/>.</summary>
        /// <param name="point">A point on the plane, m; finite.</param>
        /// <param name="normal">The normal direction; finite and non-zero (it is normalised).</param>
        /// <exception cref="System.ArgumentException">A vector is not finite, or the normal is zero.</exception>
        public Plane(Vector3d point, Vector3d normal)
        {
            Require.Finite(point, nameof(point));
            Require.NonZero(normal, nameof(normal));
            Point = point;
            Normal = normal.NormalizedOrZero();
        }

        /// <summary>
        /// The ground of a flight model: the plane through <paramref name="point"/> (default: the origin)
        /// whose normal is the model's up direction, -gravity normalised.
        /// </summary>
        /// <param name="model">The flight model; its gravity must be non-zero.</param>
        /// <param name="point">A point on the ground, m; finite.</param>
        /// <exception cref="System.ArgumentException">The model has zero gravity (no up is defined), or the point is not finite.</exception>
        public static Plane Ground(FlightModel model, Vector3d point = default)
        {
            Require.NotNull(model, nameof(model));
            if (model.Up.LengthSquared == 0)
            {
                throw new System.ArgumentException(
                    "model must have non-zero gravity to define the ground (up = -gravity); give the ground plane explicitly instead.",
                    nameof(model));
            }

            return new Plane(point, model.Up);
        }

        /// <summary>
        /// The signed distance of <paramref name="position"/> from the plane, m: positive on the normal's side. For finite
        /// input never NaN: where the point and the plane's point are so far apart (near 1e308) that the plain formula
        /// overflows, the distance is formed from quarters, so it is infinite only where it exceeds what a double holds.
        /// </summary>
        /// <param name="position">A point, m.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public double SignedDistance(in Vector3d position) => Vector3d.DotOfDifference(position, Point, Normal);

        /// <summary>The plain formula, for the flight core's quick tests, which send a non-finite value on to a search that
        /// uses <see cref="SignedDistance"/> (no check on the common step).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal double UncheckedSignedDistance(in Vector3d position) => Vector3d.PlainDotOfDifference(position, Point, Normal);

        // A quarter of the signed distance, never overflowing for finite input (Vector3d.QuarterDotOfDifference).
        private double QuarterDistance(in Vector3d position) => Vector3d.QuarterDotOfDifference(position, Point, Normal);

        /// <summary>The rate at which a ball moving with <paramref name="velocity"/> moves along the normal, m/s.</summary>
        /// <param name="velocity">A velocity, m/s.</param>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal double NormalSpeed(in Vector3d velocity) => Vector3d.Dot(velocity, Normal);

        /// <summary>The same plane with its normal reversed.</summary>
        internal Plane Flipped() => new Plane(Point, -Normal);

        /// <summary>
        /// The foot of the perpendicular from <paramref name="position"/> onto the plane. For finite input never NaN: a
        /// component is infinite only where the foot's lies beyond what a double holds.
        /// </summary>
        /// <param name="position">A point, m.</param>
        public Vector3d Project(in Vector3d position)
        {
            double d = SignedDistance(position);
            return double.IsFinite(d) ? position - Normal * d : ProjectFar(position);
        }

        // The foot where the distance exceeds double.MaxValue (the plain form gives inf * 0 = NaN beside a zero normal
        // component, and an infinite component where the foot's is finite): each component moved by 4 n q (q the quarter
        // distance, finite), and where 4 n q itself overflows, formed as 4 (p / 4 - n q) (p / 4 exact: |n q| > 2^1021 there,
        // so a subnormal p cannot matter). A zero normal component leaves the position's component as it is.
        [MethodImpl(MethodImplOptions.NoInlining)]
        private Vector3d ProjectFar(in Vector3d position)
        {
            double q = QuarterDistance(position);
            return new Vector3d(Moved(position.X, Normal.X * q), Moved(position.Y, Normal.Y * q), Moved(position.Z, Normal.Z * q));

            static double Moved(double p, double quarterShift)
            {
                double shift = 4 * quarterShift;
                return double.IsFinite(shift) ? p - shift : 4 * (0.25 * p - quarterShift);
            }
        }

        /// <inheritdoc />
        public override string ToString() => $"Plane(point={Point}, normal={Normal})";
    }
}
