// ContactShape: the base of every shape a flight can hit (box, capsule, cylinder, sphere, torus, net mesh): its id, contact
// parameters and effective mass, its signed distance (the one geometric question the sweep asks) and its bounding box.
// The search for the first touch along a step is ShapeSweep.cs; the response is Respond, through Contact.Impact.
using System;

namespace MagnusBall.Contact.Shapes
{
    /// <summary>
    /// A bounded solid the ball can hit in flight: a wall, a board, a post, the net cord, a rim. Give an array of them to a
    /// FlightStepper (or a FixedStepDriver): the first touch of the ball's surface within each step is located on the step's
    /// dense output (no tunnelling at any speed the integrator accepts), the ball is answered with spin through
    /// <see cref="Impact"/>, and a Contact flight event names the shape by its <see cref="Id"/>. Immutable; share it
    /// between balls. See docs/contacts.md.
    /// </summary>
    public abstract class ContactShape
    {
        private protected ContactShape(int id, in ContactProperties contact, double effectiveMassKg)
        {
            if (!(effectiveMassKg > 0) || double.IsNaN(effectiveMassKg))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(effectiveMassKg), effectiveMassKg,
                    $"effectiveMassKg must be > 0 kg (positive infinity for a fixed shape); got {Require.Format(effectiveMassKg)}.");
            }

            Id = id;
            Contact = contact;
            EffectiveMassKg = effectiveMassKg;
        }

        /// <summary>The caller's id for this shape, reported as the contact event's ShapeId when it is hit.</summary>
        public int Id { get; }

        /// <summary>The contact parameters of a hit (restitution, friction, grip recoil).</summary>
        public ContactProperties Contact { get; }

        /// <summary>The shape's effective mass at the contact point, kg; positive infinity for a fixed shape.</summary>
        public double EffectiveMassKg { get; }

        /// <summary>Lower corner of the shape's axis-aligned bounding box, m.</summary>
        internal Vector3d BoundsMin { get; private protected set; }

        /// <summary>Upper corner of the shape's axis-aligned bounding box, m.</summary>
        internal Vector3d BoundsMax { get; private protected set; }

        /// <summary>
        /// The signed distance from <paramref name="point"/> to the shape's surface, m (negative inside), and the unit
        /// outward normal there (the gradient of the distance). An exact distance: it changes by at most the distance the
        /// point moves (the sweep's bound rests on this).
        /// </summary>
        internal abstract double SignedDistance(in Vector3d point, out Vector3d normal);

        /// <summary>
        /// True for a convex shape (box, sphere, capsule, cylinder, a net's sheet): its signed distance is then a convex function,
        /// never below its tangent plane at any point, which bounds it far more tightly than the distance's slope alone
        /// (<see cref="ShapeSweep"/>).
        /// </summary>
        internal virtual bool IsConvex => false;

        /// <summary>
        /// The ball's velocity and spin after it touches the shape with its centre at <paramref name="position"/>, the
        /// shape's outward normal there being <paramref name="normal"/>: <see cref="Impact.Resolve(Ball, in Vector3d, in Vector3d, in Vector3d, in ImpactBody, in ContactProperties)"/>
        /// with a body at rest of mass <see cref="EffectiveMassKg"/>.
        /// </summary>
        /// <remarks>A shape lighter than the ball's mass over its restitution would be pushed along, the ball still moving into
        /// it; a shape here stays where it is, so it gives way by taking the ball's remaining speed into it: the ball leaves along
        /// its surface (no energy is added; without this the ball would touch it again at once, and again).</remarks>
        internal virtual ImpactOutcome Respond(Ball ball, in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, in Vector3d normal)
        {
            ImpactOutcome hit = Impact.Resolve(ball, position, velocity, angularVelocity,
                new ImpactBody(position - normal * ball.Radius, Vector3d.Zero, Vector3d.Zero, normal, EffectiveMassKg), Contact);
            double into = Vector3d.Dot(hit.Velocity, normal);
            if (!(into < 0) || hit.Regime == BounceRegime.None)
            {
                return hit;
            }

            Vector3d along = hit.Velocity - normal * into;
            return new ImpactOutcome(
                along, hit.AngularVelocity, (along - velocity) * ball.Mass, hit.Regime, hit.NormalRestitution, hit.IncomingNormalSpeed, hit.BodyVelocityChange);
        }

        /// <summary>A checked finite point or vector.</summary>
        private protected static Vector3d Finite(in Vector3d value, string name) => Require.Finite(value, name);

        /// <summary>A checked finite radius &gt; 0.</summary>
        private protected static double Radius(double value, string name) => Require.Positive(value, name);

        /// <summary>The bounding box of a segment inflated by a radius.</summary>
        private protected void SetBounds(in Vector3d a, in Vector3d b, double inflate)
        {
            var r = new Vector3d(inflate, inflate, inflate);
            BoundsMin = new Vector3d(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z)) - r;
            BoundsMax = new Vector3d(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z)) + r;
        }

        /// <summary>
        /// The offset <paramref name="rel"/> split about the unit axis <paramref name="unitAxis"/>: its part along the axis, and its
        /// distance from the axis with the unit direction away from it (any perpendicular for a point on the axis).
        /// </summary>
        private protected static Vector3d AroundAxis(in Vector3d rel, in Vector3d unitAxis, out double along, out double distance)
        {
            along = Vector3d.Dot(rel, unitAxis);
            Vector3d radial = rel - unitAxis * along;
            distance = radial.Length;
            return distance > 0 ? radial / distance : CapsuleShape.AnyPerpendicular(unitAxis);
        }

        /// <summary>A unit vector from a finite non-zero one.</summary>
        private protected static Vector3d Unit(in Vector3d value, string name) => Require.NonZero(value, name).NormalizedOrZero();

        /// <summary>The length of the segment from a to b, refused below 1e-150 m (where its square would underflow) or infinite.</summary>
        private protected static double AxisLength(in Vector3d a, in Vector3d b, string name)
        {
            double length = (b - a).Length;
            if (!(length >= 1e-150) || !double.IsFinite(length))
            {
                throw new ArgumentException($"{name} must lie between 1e-150 m and a finite distance from the other end; got {a} to {b}.", name);
            }

            return length;
        }
    }
}
