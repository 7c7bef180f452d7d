using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A torus: every point within <see cref="TubeRadiusM"/> of the circle of radius <see cref="RingRadiusM"/> about
    /// <see cref="Centre"/> in the plane normal to <see cref="Axis"/>. A basketball rim (MagnusBall.Shots.SportShapes.BasketballHoop builds one).
    /// </summary>
    public sealed class TorusShape : ContactShape
    {
        /// <summary>Creates a torus.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="centre">The centre of the ring, m; finite.</param>
        /// <param name="axis">The ring's axis (normal to its plane); finite, non-zero (it is normalised).</param>
        /// <param name="ringRadiusM">The radius of the ring's centre line, m; finite and &gt; 0.</param>
        /// <param name="tubeRadiusM">The radius of the tube, m; finite, &gt; 0.</param>
        /// <param name="contact">The contact parameters of a hit.</param>
        /// <param name="effectiveMassKg">The effective mass at the contact, kg; &gt; 0, positive infinity (the default) for a fixed shape.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public TorusShape(int id, Vector3d centre, Vector3d axis, double ringRadiusM, double tubeRadiusM, ContactProperties contact,
            double effectiveMassKg = double.PositiveInfinity)
            : base(id, contact, effectiveMassKg)
        {
            Centre = Finite(centre, nameof(centre));
            Axis = Unit(axis, nameof(axis));
            RingRadiusM = Radius(ringRadiusM, nameof(ringRadiusM));
            TubeRadiusM = Radius(tubeRadiusM, nameof(tubeRadiusM));
            double reach = ringRadiusM + tubeRadiusM;
            SetBounds(centre, centre, reach);
        }

        /// <summary>The centre of the ring, m.</summary>
        public Vector3d Centre { get; }

        /// <summary>The unit axis of the ring.</summary>
        public Vector3d Axis { get; }

        /// <summary>The radius of the ring's centre line, m.</summary>
        public double RingRadiusM { get; }

        /// <summary>The radius of the tube, m.</summary>
        public double TubeRadiusM { get; }

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal)
        {
            Vector3d radialUnit = AroundAxis(point - Centre, Axis, out double along, out double r);
            Vector3d nearest = Centre + radialUnit * RingRadiusM; // the nearest point of the ring's centre line
            Vector3d offset = point - nearest;
            double d = offset.Length;
            normal = d > 0 ? offset / d : Axis;
            return d - TubeRadiusM;
        }
    }
}
