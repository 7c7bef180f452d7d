using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A bounded box, oriented: the points whose offsets from <see cref="Centre"/> along its three axes are within its half
    /// extents. A half extent of zero makes it a rectangle with no thickness (<see cref="Rectangle"/>), hit from either side:
    /// a wall, a board, a backboard, a table top, the side of a goal.
    /// </summary>
    public sealed class BoxShape : ContactShape
    {
        private readonly Vector3d _x, _y, _z;

        /// <summary>Creates a box.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="centre">The centre, m; finite.</param>
        /// <param name="halfExtentsM">Half the box's size along its x, y and z axes, m; each finite and &gt;= 0.</param>
        /// <param name="xAxis">The box's x axis; finite, non-zero (it is normalised).</param>
        /// <param name="yAxis">A direction in the box's x-y plane, not along x (its part across x is the y axis); z is x cross y.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0, positive infinity (the default) for a fixed shape.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public BoxShape(int id, Vector3d centre, Vector3d halfExtentsM, Vector3d xAxis, Vector3d yAxis, ContactProperties contact,
            double effectiveMassKg = double.PositiveInfinity)
            : base(id, contact, effectiveMassKg)
        {
            Centre = Finite(centre, nameof(centre));
            Finite(halfExtentsM, nameof(halfExtentsM));
            int zeros = (halfExtentsM.X == 0 ? 1 : 0) + (halfExtentsM.Y == 0 ? 1 : 0) + (halfExtentsM.Z == 0 ? 1 : 0);
            if (!(halfExtentsM.X >= 0 && halfExtentsM.Y >= 0 && halfExtentsM.Z >= 0) || zeros > 1)
            {
                throw new ArgumentException(
                    $"halfExtentsM must have every component finite and >= 0 m, at most one of them 0 (a rectangle); got {halfExtentsM}.", nameof(halfExtentsM));
            }

            HalfExtentsM = halfExtentsM;
            _x = Unit(xAxis, nameof(xAxis));
            Vector3d y = Require.NonZero(yAxis, nameof(yAxis));
            y -= _x * Vector3d.Dot(y, _x);
            if (!(y.Length > 1e-9 * yAxis.Length))
            {
                throw new ArgumentException($"yAxis must not be parallel to xAxis; got xAxis {xAxis}, yAxis {yAxis}.", nameof(yAxis));
            }

            _y = y.NormalizedOrZero();
            _z = Vector3d.Cross(_x, _y);
            // The bounding box: the sum of the extents' reach along each world axis.
            var reach = new Vector3d(
                Math.Abs(_x.X) * halfExtentsM.X + Math.Abs(_y.X) * halfExtentsM.Y + Math.Abs(_z.X) * halfExtentsM.Z,
                Math.Abs(_x.Y) * halfExtentsM.X + Math.Abs(_y.Y) * halfExtentsM.Y + Math.Abs(_z.Y) * halfExtentsM.Z,
                Math.Abs(_x.Z) * halfExtentsM.X + Math.Abs(_y.Z) * halfExtentsM.Y + Math.Abs(_z.Z) * halfExtentsM.Z);
            BoundsMin = centre - reach;
            BoundsMax = centre + reach;
        }

        /// <summary>
        /// A rectangle with no thickness: centre <paramref name="centre"/>, face normal <paramref name="normal"/>,
        /// <paramref name="widthM"/> along <paramref name="widthDirection"/> (its part across the normal) and
        /// <paramref name="heightM"/> along normal cross width.
        /// </summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="centre">The centre, m; finite.</param>
        /// <param name="normal">The face normal; finite, non-zero.</param>
        /// <param name="widthDirection">The direction of the width; finite, not along the normal.</param>
        /// <param name="widthM">The width, m; finite and &gt; 0.</param>
        /// <param name="heightM">The height, m; finite and &gt; 0.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0 or positive infinity.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public static BoxShape Rectangle(int id, Vector3d centre, Vector3d normal, Vector3d widthDirection, double widthM, double heightM,
            ContactProperties contact, double effectiveMassKg = double.PositiveInfinity)
        {
            Vector3d n = Unit(normal, nameof(normal));
            Require.Positive(widthM, nameof(widthM));
            Require.Positive(heightM, nameof(heightM));
            // x = width, y = height = n x width, z = x cross y = n.
            Vector3d w = Require.NonZero(widthDirection, nameof(widthDirection));
            w -= n * Vector3d.Dot(w, n);
            if (!(w.Length > 1e-9 * widthDirection.Length))
            {
                throw new ArgumentException($"widthDirection must not be along the normal; got normal {normal}, widthDirection {widthDirection}.", nameof(widthDirection));
            }

            w = w.NormalizedOrZero();
            return new BoxShape(id, centre, new Vector3d(widthM * 0.5, heightM * 0.5, 0), w, Vector3d.Cross(n, w), contact, effectiveMassKg);
        }

        /// <summary>The centre, m.</summary>
        public Vector3d Centre { get; }

        /// <summary>Half the box's size along its x, y and z axes, m.</summary>
        public Vector3d HalfExtentsM { get; }

        /// <summary>The box's unit z axis (x cross y): a rectangle's face normal.</summary>
        public Vector3d ZAxis => _z;

        /// <summary>The box's eight corners (a rectangle's four, each twice), m: for drawing it.</summary>
        internal Vector3d[] Corners()
        {
            var corners = new Vector3d[8];
            for (int i = 0; i < 8; i++)
            {
                corners[i] = Centre + _x * ((i & 1) == 0 ? -HalfExtentsM.X : HalfExtentsM.X) + _y * ((i & 2) == 0 ? -HalfExtentsM.Y : HalfExtentsM.Y) +
                    _z * ((i & 4) == 0 ? -HalfExtentsM.Z : HalfExtentsM.Z);
            }

            return corners;
        }

        /// <inheritdoc />
        internal override bool IsConvex => true;

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal)
        {
            Vector3d rel = point - Centre;
            double lx = Vector3d.Dot(rel, _x), ly = Vector3d.Dot(rel, _y), lz = Vector3d.Dot(rel, _z);
            double qx = Math.Abs(lx) - HalfExtentsM.X, qy = Math.Abs(ly) - HalfExtentsM.Y, qz = Math.Abs(lz) - HalfExtentsM.Z;
            if (qx > 0 || qy > 0 || qz > 0)
            {
                double ox = qx > 0 ? (lx < 0 ? -qx : qx) : 0;
                double oy = qy > 0 ? (ly < 0 ? -qy : qy) : 0;
                double oz = qz > 0 ? (lz < 0 ? -qz : qz) : 0;
                double d = Math.Sqrt(ox * ox + oy * oy + oz * oz);
                normal = (_x * ox + _y * oy + _z * oz) / d;
                return d;
            }

            // Inside (or on a face): the nearest face.
            if (qz >= qx && qz >= qy)
            {
                normal = lz < 0 ? -_z : _z;
                return qz;
            }

            if (qy >= qx)
            {
                normal = ly < 0 ? -_y : _y;
                return qy;
            }

            normal = lx < 0 ? -_x : _x;
            return qx;
        }
    }
}
