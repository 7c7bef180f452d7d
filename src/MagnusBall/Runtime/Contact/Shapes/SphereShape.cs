using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A sphere: every point within <see cref="RadiusM"/> of <see cref="Centre"/>. A bumper, a round obstacle, another ball
    /// held still (or given its mass as the effective mass), Unity's SphereCollider.
    /// </summary>
    public sealed class SphereShape : ContactShape
    {
        /// <summary>Creates a sphere.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="centre">The centre, m; finite.</param>
        /// <param name="radiusM">The radius, m; finite and &gt; 0.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0, positive infinity (the default) for a fixed shape.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public SphereShape(int id, Vector3d centre, double radiusM, ContactProperties contact, double effectiveMassKg = double.PositiveInfinity)
            : base(id, contact, effectiveMassKg)
        {
            Centre = Finite(centre, nameof(centre));
            RadiusM = Radius(radiusM, nameof(radiusM));
            SetBounds(centre, centre, radiusM);
        }

        /// <summary>The centre, m.</summary>
        public Vector3d Centre { get; }

        /// <summary>The radius, m.</summary>
        public double RadiusM { get; }

        /// <inheritdoc />
        internal override bool IsConvex => true;

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal)
        {
            Vector3d offset = point - Centre;
            double d = offset.Length;
            normal = d > 0 ? offset / d : Vector3d.UnitX; // at the centre itself any direction is outward
            return d - RadiusM;
        }
    }
}
