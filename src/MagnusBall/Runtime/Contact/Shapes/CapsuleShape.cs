using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A straight capsule: every point within <see cref="RadiusM"/> of the segment from <see cref="EndA"/> to
    /// <see cref="EndB"/> (a cylinder with round ends). A goal post or crossbar (round section), the net cord or tape, a rail.
    /// </summary>
    public sealed class CapsuleShape : ContactShape
    {
        private readonly Vector3d _axis;   // B - A
        private readonly double _axisLengthSquared;

        /// <summary>Creates a capsule.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="endA">One end of the axis, m; finite.</param>
        /// <param name="endB">The other end, m; finite, different from <paramref name="endA"/>.</param>
        /// <param name="radiusM">The radius, m; finite and &gt; 0.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0, positive infinity (the default) for a fixed shape.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public CapsuleShape(int id, Vector3d endA, Vector3d endB, double radiusM, ContactProperties contact, double effectiveMassKg = double.PositiveInfinity)
            : base(id, contact, effectiveMassKg)
        {
            EndA = Finite(endA, nameof(endA));
            EndB = Finite(endB, nameof(endB));
            RadiusM = Radius(radiusM, nameof(radiusM));
            AxisLength(endA, endB, nameof(endB));
            _axis = endB - endA;
            _axisLengthSquared = _axis.LengthSquared;
            SetBounds(endA, endB, radiusM);
        }

        /// <summary>One end of the axis, m.</summary>
        public Vector3d EndA { get; }

        /// <summary>The other end of the axis, m.</summary>
        public Vector3d EndB { get; }

        /// <summary>The radius, m.</summary>
        public double RadiusM { get; }

        /// <inheritdoc />
        internal override bool IsConvex => true;

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal)
        {
            Vector3d fromA = point - EndA;
            double s = Vector3d.Dot(fromA, _axis) / _axisLengthSquared;
            s = s < 0 ? 0 : s > 1 ? 1 : s;
            Vector3d offset = fromA - _axis * s;
            double d = offset.Length;
            normal = d > 0 ? offset / d : AnyPerpendicular(_axis);
            return d - RadiusM;
        }

        /// <summary>A unit vector perpendicular to <paramref name="axis"/> (the normal on the axis itself, where any will do).</summary>
        internal static Vector3d AnyPerpendicular(in Vector3d axis)
        {
            Vector3d other = Math.Abs(axis.X) < Math.Abs(axis.Y) ? Vector3d.UnitX : Vector3d.UnitY;
            return Vector3d.Cross(axis, other).NormalizedOrZero();
        }
    }
}
