using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// The mesh of a net as a catching surface: a rectangle with no thickness that a ball hitting it loses most of its speed
    /// to and drops from. The model (a game model, with its parameters; no measurement is fitted): the impact law
    /// (<see cref="Impact"/>) with the mesh's contact parameters (by default a normal restitution of 0.1 and full grip), then
    /// the ball keeps <see cref="TangentialSpeedKept"/> of its velocity along the mesh and of its spin (the mesh wraps the ball
    /// and takes the rest). A tennis ball at 30 m/s into the mesh leaves it at 3 m/s back and drops.
    /// </summary>
    public sealed class NetMeshShape : ContactShape
    {
        /// <summary>The mesh's default contact parameters: normal restitution 0.1, friction 1, no grip recoil.</summary>
        public static readonly ContactProperties DefaultContact = new ContactProperties(0.1, 1.0);

        /// <summary>The default <see cref="TangentialSpeedKept"/>, 0.25.</summary>
        internal const double DefaultTangentialSpeedKept = 0.25;

        private readonly BoxShape _sheet;

        /// <summary>Creates a net mesh.</summary>
        /// <param name="id">The caller's id, reported when it is hit.</param>
        /// <param name="centre">The centre of the mesh, m; finite.</param>
        /// <param name="normal">The mesh's face normal; finite, non-zero (either side catches).</param>
        /// <param name="widthDirection">The direction along the mesh's width; finite, not along the normal.</param>
        /// <param name="widthM">The width, m; finite and &gt; 0.</param>
        /// <param name="heightM">The height (along normal cross width), m; finite and &gt; 0.</param>
        /// <param name="tangentialSpeedKept">The fraction of the ball's velocity along the mesh and of its spin it keeps after the hit; in [0, 1].</param>
        /// <param name="effectiveMassKg">The mass of mesh that moves with the ball at the hit, kg; &gt; 0, positive infinity (the
        /// default) for a mesh held still. A light mesh gives way: the ball leaves it slower along the normal than off a fixed one.</param>
        /// <exception cref="ArgumentException">A value is outside its range (the message names it); nothing is created.</exception>
        public NetMeshShape(int id, Vector3d centre, Vector3d normal, Vector3d widthDirection, double widthM, double heightM,
            double tangentialSpeedKept = DefaultTangentialSpeedKept, double effectiveMassKg = double.PositiveInfinity)
            : base(id, DefaultContact, effectiveMassKg)
        {
            TangentialSpeedKept = Require.InRange(tangentialSpeedKept, 0, 1, nameof(tangentialSpeedKept));
            _sheet = BoxShape.Rectangle(id, centre, normal, widthDirection, widthM, heightM, DefaultContact);
            BoundsMin = _sheet.BoundsMin;
            BoundsMax = _sheet.BoundsMax;
        }

        /// <summary>The mesh's sheet (a rectangle), for drawing it.</summary>
        internal BoxShape Sheet => _sheet;

        /// <summary>The fraction of the ball's velocity along the mesh and of its spin it keeps after the hit.</summary>
        public double TangentialSpeedKept { get; }

        /// <inheritdoc />
        internal override bool IsConvex => true;

        /// <inheritdoc />
        internal override double SignedDistance(in Vector3d point, out Vector3d normal) => _sheet.SignedDistance(point, out normal);

        /// <inheritdoc />
        internal override ImpactOutcome Respond(Ball ball, in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, in Vector3d normal)
        {
            ImpactOutcome hit = base.Respond(ball, position, velocity, angularVelocity, normal);
            if (hit.Regime == BounceRegime.None)
            {
                return hit;
            }

            double vn = Vector3d.Dot(hit.Velocity, normal);
            Vector3d v = normal * vn + (hit.Velocity - normal * vn) * TangentialSpeedKept;
            Vector3d w = hit.AngularVelocity * TangentialSpeedKept;
            Vector3d impulse = (v - velocity) * ball.Mass;
            return new ImpactOutcome(v, w, impulse, hit.Regime, hit.NormalRestitution, hit.IncomingNormalSpeed, Vector3d.Zero);
        }
    }
}
