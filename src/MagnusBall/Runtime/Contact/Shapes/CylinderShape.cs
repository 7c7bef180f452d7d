using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A straight cylinder of finite length with flat ends: every point within <see cref="RadiusM"/> of the axis from
    /// <see cref="EndA"/> to <see cref="EndB"/> and between the two end planes. A post with a flat top (a net post, a
    /// basketball pole), a crossbar with square-cut ends.
    /// </summary>
    public sealed class CylinderShape : ContactShape
    {
        private readonly Vector3d _unitAxis;
        private readonly double _halfLength;
        private readonly Vector3d _centre;

        /// <summary>Creates a cylinder.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="endA">Centre of one end face, m; finite.</param>
        /// <param name="endB">Centre of the other end face, m; finite, different from <paramref name="endA"/>.</param>
        /// <param name="radiusM">The radius, m; finite and &gt; 0.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0, positive infinity (the default) for a fixed shape.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public CylinderShape(int id, Vector3d endA, Vector3d endB, double radiusM, ContactProperties contact, double effectiveMassKg = double.PositiveInfinity)
            : base(id, contact, effectiveMassKg)
        {
            EndA = Finite(endA, nameof(endA));
            EndB = Finite(endB, nameof(endB));
            RadiusM = Radius(radiusM, nameof(radiusM));
            double length = AxisLength(endA, endB, nameof(endB));
            _unitAxis = (endB - endA) / length;
            _halfLength = 0.5 * length;
            _centre = (endA + endB) * 0.5;
            SetBounds(endA, endB, radiusM);
        }

        /// <summary>Centre of one end face, m.</summary>
        public Vector3d EndA { get; }

        /// <summary>Centre of the other end face, m.</summary>
        public Vector3d EndB { get; }

        /// <summary>The radius, m.</summary>
        public double RadiusM { get; }

        /// <inheritdoc />
        internal override bool IsConvex => true;

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal)
        {
            Vector3d radialUnit = AroundAxis(point - _centre, _unitAxis, out double along, out double r);
            Vector3d axisUnit = along >= 0 ? _unitAxis : -_unitAxis;
            double dr = r - RadiusM;                    // outside the side when > 0
            double da = Math.Abs(along) - _halfLength;  // beyond an end when > 0
            if (dr > 0 && da > 0)
            {
                // Nearest the rim of an end face.
                double d = Math.Sqrt(dr * dr + da * da);
                normal = (radialUnit * dr + axisUnit * da) / d;
                return d;
            }

            if (dr >= da)
            {
                normal = radialUnit;
                return dr;
            }

            normal = axisUnit;
            return da;
        }
    }
}
