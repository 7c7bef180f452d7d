using System;

namespace MagnusBall.Stepping
{
    /// <summary>
    /// A plane a driver watches for crossings (a net, a baseline, a goal line): a point on it and a unit
    /// normal. It counts as crossed when the ball's centre goes through it along the normal.
    /// </summary>
    public readonly struct FlightPlane
    {
        /// <summary>A point on the plane, m.</summary>
        public readonly Vector3d Point;

        /// <summary>The unit normal: the crossing direction that counts.</summary>
        public readonly Vector3d Normal;

        /// <summary>Creates a plane.</summary>
        /// <param name="point">A point on the plane, m; finite.</param>
        /// <param name="normal">The crossing direction; finite, non-zero (it is normalised).</param>
        /// <exception cref="ArgumentException">A vector is not finite, or the normal is zero.</exception>
        public FlightPlane(Vector3d point, Vector3d normal)
        {
            Point = Require.Finite(point, nameof(point));
            Normal = Require.NonZero(normal, nameof(normal)).NormalizedOrZero();
        }

        /// <summary>The signed distance of <paramref name="position"/> from the plane along its normal, m.</summary>
        /// <param name="position">A position, m.</param>
        public double SignedDistance(in Vector3d position) => Vector3d.Dot(position - Point, Normal);

        /// <inheritdoc />
        public override string ToString() => $"Plane(point={Point}, normal={Normal})";
    }
}
