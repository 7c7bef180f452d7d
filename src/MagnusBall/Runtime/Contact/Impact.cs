using System;

namespace MagnusBall.Contact
{
    /// <summary>
    /// The body a ball hits, at the moment of contact: how its surface moves, which way its face points and how
    /// heavy it feels at the contact point. A racket, a club head, a bat, a foot, a wall, the ground.
    /// </summary>
    /// <remarks>
    /// The body is rigid for the duration of the impact and responds at the contact point like a free point mass
    /// <see cref="EffectiveMass"/> in every direction (the same effective mass along the normal and along the face:
    /// an assumption, see docs/impacts.md). Its surface velocity at the contact point is
    /// <see cref="Velocity"/> + <see cref="AngularVelocity"/> x (contact - <see cref="Point"/>); the angular velocity
    /// matters only through that velocity (the impact is instantaneous).
    /// </remarks>
    public readonly struct ImpactBody
    {
        /// <summary>A reference point on the body (for example its centre of mass, or the point of the face that is hit), m.</summary>
        public readonly Vector3d Point;

        /// <summary>The velocity of <see cref="Point"/>, m/s.</summary>
        public readonly Vector3d Velocity;

        /// <summary>The body's angular velocity, rad/s, in the frame's own rotation convention.</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>The unit normal of the body's face at the contact, pointing out of the body toward the ball.</summary>
        public readonly Vector3d Normal;

        /// <summary>The body's effective mass at the contact point, kg; <see cref="double.PositiveInfinity"/> for an immovable body.</summary>
        public readonly double EffectiveMass;

        /// <summary>Creates a body.</summary>
        /// <param name="point">A reference point on the body, m; finite.</param>
        /// <param name="velocity">The velocity of that point, m/s; finite.</param>
        /// <param name="angularVelocity">The body's angular velocity, rad/s; finite.</param>
        /// <param name="normal">The face normal at the contact, toward the ball; finite, non-zero (it is normalised).</param>
        /// <param name="effectiveMass">The effective mass at the contact point, kg; &gt; 0, or positive infinity for an immovable body.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public ImpactBody(in Vector3d point, in Vector3d velocity, in Vector3d angularVelocity, in Vector3d normal, double effectiveMass)
        {
            Point = Require.Finite(point, nameof(point));
            Velocity = Require.Finite(velocity, nameof(velocity));
            AngularVelocity = Require.Finite(angularVelocity, nameof(angularVelocity));
            Normal = Require.NonZero(normal, nameof(normal)).NormalizedOrZero();
            if (!(effectiveMass > 0))
            {
                throw new ArgumentOutOfRangeException(
                    nameof(effectiveMass), effectiveMass, $"effectiveMass must be > 0 kg (positive infinity for an immovable body); got {Require.Format(effectiveMass)}.");
            }

            EffectiveMass = effectiveMass;
        }

        /// <summary>A body whose face moves with one velocity (no rotation), with the given effective mass.</summary>
        /// <param name="velocity">The face's velocity, m/s; finite.</param>
        /// <param name="normal">The face normal toward the ball; finite, non-zero.</param>
        /// <param name="effectiveMass">The effective mass at the contact point, kg; &gt; 0 or positive infinity.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public static ImpactBody Moving(in Vector3d velocity, in Vector3d normal, double effectiveMass) =>
            new ImpactBody(Vector3d.Zero, velocity, Vector3d.Zero, normal, effectiveMass);

        /// <summary>An immovable body at rest (the ground, a wall) with face normal <paramref name="normal"/>.</summary>
        /// <param name="normal">The face normal toward the ball; finite, non-zero.</param>
        /// <exception cref="ArgumentException">The normal is zero or not finite.</exception>
        public static ImpactBody Immovable(in Vector3d normal) =>
            new ImpactBody(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero, normal, double.PositiveInfinity);

        /// <summary>The velocity of the body's surface at <paramref name="contactPoint"/>: V + Omega x (contact - point), m/s.</summary>
        /// <param name="contactPoint">A point of the body, m.</param>
        internal Vector3d SurfaceVelocityAt(in Vector3d contactPoint) => Velocity + Vector3d.Cross(AngularVelocity, contactPoint - Point);

        /// <inheritdoc />
        public override string ToString() => $"ImpactBody(point={Point}, v={Velocity}, w={AngularVelocity}, n={Normal}, M={EffectiveMass:R} kg)";
    }

    /// <summary>The result of one impact: the ball's velocity and spin just after it, the impulse, the regime.</summary>
    public readonly struct ImpactOutcome
    {
        /// <summary>The ball's velocity just after the impact, m/s (in the caller's frame, not the body's).</summary>
        public readonly Vector3d Velocity;

        /// <summary>The ball's angular velocity just after the impact, rad/s.</summary>
        public readonly Vector3d AngularVelocity;

        /// <summary>The impulse the body gave the ball, N s: m (v2 - v1). The body got minus this.</summary>
        public readonly Vector3d Impulse;

        /// <summary>How the contact point behaved: slid throughout, gripped, or no impact (the ball was not approaching the face).</summary>
        public readonly BounceRegime Regime;

        /// <summary>The normal COR e applied (0 when <see cref="Regime"/> is None).</summary>
        public readonly double NormalRestitution;

        /// <summary>The ball's speed into the face relative to it, m/s (0 when not approaching).</summary>
        public readonly double IncomingNormalSpeed;

        /// <summary>
        /// The change of the body's surface velocity at the contact point, m/s: -Impulse / EffectiveMass (zero for an immovable
        /// body); for a rigid club head (<see cref="Swings.ClubSwing"/> with a rotating <see cref="Swings.ClubHead"/>) it includes the
        /// head's rotation about its centre of gravity: -(Impulse / M + (I^-1 (r x Impulse)) x r), r from the CG to the contact.
        /// </summary>
        public readonly Vector3d BodyVelocityChange;

        /// <summary>Creates an outcome.</summary>
        /// <param name="velocity">Outgoing velocity, m/s.</param>
        /// <param name="angularVelocity">Outgoing angular velocity, rad/s.</param>
        /// <param name="impulse">Impulse on the ball, N s.</param>
        /// <param name="regime">The regime.</param>
        /// <param name="normalRestitution">The normal COR applied.</param>
        /// <param name="incomingNormalSpeed">The relative incoming normal speed, m/s.</param>
        /// <param name="bodyVelocityChange">The body's velocity change at the contact, m/s.</param>
        public ImpactOutcome(
            in Vector3d velocity, in Vector3d angularVelocity, in Vector3d impulse, BounceRegime regime, double normalRestitution,
            double incomingNormalSpeed, in Vector3d bodyVelocityChange)
        {
            Velocity = velocity;
            AngularVelocity = angularVelocity;
            Impulse = impulse;
            Regime = regime;
            NormalRestitution = normalRestitution;
            IncomingNormalSpeed = incomingNormalSpeed;
            BodyVelocityChange = bodyVelocityChange;
        }

        /// <summary>The ball's speed after the impact, m/s.</summary>
        internal double Speed => Velocity.Length;

        /// <summary>The ball's spin rate after the impact, rad/s.</summary>
        internal double SpinRate => AngularVelocity.Length;

        /// <summary>The ball's state after the impact at <paramref name="position"/> and <paramref name="time"/>.</summary>
        /// <param name="position">The ball's centre, m.</param>
        /// <param name="time">The time, s.</param>
        public FlightState LaunchState(in Vector3d position, double time = 0) => new FlightState(position, Velocity, AngularVelocity, time);

        /// <inheritdoc />
        public override string ToString() => $"{Regime}: v={Velocity} w={AngularVelocity} J={Impulse} e={NormalRestitution:R}";
    }

    /// <summary>
    /// The impact of a spinning ball with a moving body of finite effective mass: Cross's slide/grip contact
    /// (the same law as <see cref="CrossBounce"/>, which is this law with an immovable body at rest), computed in
    /// the body's frame. Allocation-free and thread-safe.
    /// </summary>
    /// <remarks>
    /// <para>In the frame moving with the body's surface at the contact point, write kappa = m/M (ball mass over the
    /// body's effective mass; 0 for an immovable body) and alpha' = alpha (1 + kappa). The relative normal velocity
    /// reverses with the COR e: the ball's normal velocity becomes (e - kappa)/(1 + kappa) vn, so its normal
    /// velocity change is J = (1 + e) vn/(1 + kappa). A body moving at V into a ball moving at v along the normal
    /// sends it off at e_A v + (1 + e_A) V with the apparent COR e_A = (e - kappa)/(1 + kappa) (Brody, Cross &amp;
    /// Lindsey 2002, ch. 11; Nathan 2003's collision efficiency q is the same number).</para>
    /// <para>Along the face, with the relative tangential velocity of the centre v_r and Omega = R (n x w),
    /// Cross's two vectors become u = v_r + Omega (the slip) and Lam' = v_r - alpha' Omega. A friction impulse
    /// leaves Lam' unchanged and changes u by (1 + alpha') F/(alpha m); the normal-force offset D changes Lam' by
    /// -(1 + kappa) delta and u by delta/alpha. The slide and grip then follow CrossBounce's equations with alpha'
    /// in place of alpha; with kappa = 0 every operation is the ground bounce's, bit for bit. The two bodies'
    /// kinetic energy relative to their centre of mass is m/(2(1 + kappa)) [vn_r^2 + (|Lam'|^2 + alpha' |u|^2)/(1 + alpha')]
    /// plus the spin about the normal, and none of these grows, so no impact creates energy (for a body at
    /// rest, the ball never leaves with more kinetic energy than it came with).</para>
    /// </remarks>
    public static class Impact
    {
        private static readonly double InverseSqrt2 = 1.0 / Math.Sqrt(2.0);

        /// <summary>
        /// The ball's velocity and spin after it hits <paramref name="body"/> (or the body hits it), with contact
        /// parameters <paramref name="contact"/>.
        /// </summary>
        /// <param name="ball">The ball (mass, radius and moment-of-inertia factor matter); not null.</param>
        /// <param name="position">The ball's centre at contact, m; finite (the contact point is one radius from it against the normal).</param>
        /// <param name="velocity">The ball's velocity before the impact, m/s; finite.</param>
        /// <param name="angularVelocity">The ball's angular velocity before the impact, rad/s; finite.</param>
        /// <param name="body">The body hit; its normal must be non-zero and its effective mass at least 1e-12 of the ball's (not the default value).</param>
        /// <param name="contact">The contact parameters (restitution, friction, grip recoil, force offset).</param>
        /// <returns>
        /// The outgoing state. A ball not approaching the face in the body's frame comes back unchanged with
        /// <see cref="BounceRegime.None"/> and zero impulse.
        /// </returns>
        /// <exception cref="ArgumentException">An argument is null or not finite, the body is the default value, its effective mass is below
        /// 1e-12 of the ball's, or its surface velocity at the contact point is beyond 2^600 times the largest double (an angular
        /// velocity near 1e308 rad/s with a lever near 1e308 m); the message names it.</exception>
        public static ImpactOutcome Resolve(
            Ball ball, in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, in ImpactBody body, in ContactProperties contact)
        {
            CheckArguments(ball, position, velocity, angularVelocity, body);

            Vector3d n = body.Normal;
            Vector3d contactPoint = position - n * ball.Radius;
            Vector3d surfaceVelocity = body.SurfaceVelocityAt(contactPoint);
            double kappa = ball.Mass / body.EffectiveMass; // 0 for an immovable body
            Vector3d relative = velocity - surfaceVelocity;
            if (!IsModerate(relative, angularVelocity, ball.Radius))
            {
                return ResolveLarge(ball, velocity, angularVelocity, body, contactPoint, kappa, contact);
            }

            Resolve(ball.Radius, ball.InertiaFactor, kappa, n, relative, angularVelocity, contact,
                out Vector3d relative2, out Vector3d spin2, out BounceRegime regime, out double e, out double vn);
            if (regime == BounceRegime.None)
            {
                return new ImpactOutcome(velocity, angularVelocity, Vector3d.Zero, BounceRegime.None, 0, 0, Vector3d.Zero);
            }

            Vector3d velocity2 = relative2 + surfaceVelocity;
            Vector3d impulse = (relative2 - relative) * ball.Mass;
            Vector3d bodyChange = double.IsPositiveInfinity(body.EffectiveMass) ? Vector3d.Zero : impulse * (-1.0 / body.EffectiveMass);
            return new ImpactOutcome(velocity2, spin2, impulse, regime, e, vn, bodyChange);
        }

        // Speeds, spins and spin surface speeds within 2^500 (m/s, rad/s), where the law's products cannot overflow (the
        // spin's own size too: n x w is formed before the radius multiplies it); false for a relative velocity that
        // overflowed to infinity or NaN.
        private static bool IsModerate(in Vector3d relative, in Vector3d angularVelocity, double radius)
        {
            double spin = angularVelocity.MaxAbsComponent;
            return relative.MaxAbsComponent <= LargeSpeed && spin <= LargeSpeed && spin * radius <= LargeSpeed;
        }

        // Every velocity times 2^-600, exactly (see the law's own scaled path): the surface's velocity at the contact point
        // formed from the scaled body motion, its lever halved (and the spin doubled) where the lever overflows.
        private static Vector3d ScaledSurfaceVelocity(in ImpactBody body, in Vector3d contactPoint)
        {
            Vector3d lever = contactPoint - body.Point;
            Vector3d spin = body.AngularVelocity * ScaleDown;
            if (!lever.IsFinite)
            {
                lever = contactPoint * 0.5 - body.Point * 0.5;
                spin *= 2;
            }

            Vector3d surface = body.Velocity * ScaleDown + Vector3d.Cross(spin, lever);
            if (!surface.IsFinite)
            {
                throw new ArgumentException(
                    "body's surface velocity at the contact point (its angular velocity times the lever from its point) is beyond "
                    + "2^600 times the largest double; no impact can be formed.", "body");
            }

            return surface;
        }

        // Resolve for speeds beyond 2^500 m/s or a relative velocity beyond a double: the law at 2^-600 of every velocity
        // (the offset at the true speed), scaled back; finite, or infinite where the true value is beyond a double, never NaN.
        private static ImpactOutcome ResolveLarge(
            Ball ball, in Vector3d velocity, in Vector3d angularVelocity, in ImpactBody body, in Vector3d contactPoint, double kappa,
            in ContactProperties contact)
        {
            Vector3d surface = ScaledSurfaceVelocity(body, contactPoint);
            Vector3d relative = velocity * ScaleDown - surface;
            Resolve(ball.Radius, ball.InertiaFactor, kappa, body.Normal, relative, angularVelocity * ScaleDown,
                Math.Min(relative.Length * ScaleUp, double.MaxValue), contact,
                out Vector3d relative2, out Vector3d spin2, out BounceRegime regime, out double e, out double vn);
            if (regime == BounceRegime.None)
            {
                return new ImpactOutcome(velocity, angularVelocity, Vector3d.Zero, BounceRegime.None, 0, 0, Vector3d.Zero);
            }

            Vector3d impulse = (relative2 - relative) * ball.Mass * ScaleUp; // the mass first: finite wherever the true impulse is
            Vector3d bodyChange = double.IsPositiveInfinity(body.EffectiveMass) ? Vector3d.Zero : impulse * (-1.0 / body.EffectiveMass);
            return new ImpactOutcome((relative2 + surface) * ScaleUp, spin2 * ScaleUp, impulse, regime, e, vn * ScaleUp, bodyChange);
        }

        // The checks both Resolve overloads make before anything is computed.
        private static void CheckArguments(Ball ball, in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, in ImpactBody body)
        {
            Require.NotNull(ball, nameof(ball));
            Require.Finite(position, nameof(position));
            Require.Finite(velocity, nameof(velocity));
            Require.Finite(angularVelocity, nameof(angularVelocity));
            if (!(body.EffectiveMass > 0) || body.Normal.LengthSquared == 0)
            {
                throw new ArgumentException(
                    "body must be built by an ImpactBody constructor (a non-zero normal and an effective mass > 0 kg); got the default value.", nameof(body));
            }

            if (!(ball.Mass / body.EffectiveMass <= MaximumMassRatio))
            {
                throw new ArgumentException(
                    $"body's effective mass must be at least {Require.Format(1 / MaximumMassRatio)} of the ball's {Require.Format(ball.Mass)} kg "
                    + $"(a lighter body overflows the law's mass ratio); got {Require.Format(body.EffectiveMass)} kg.", nameof(body));
            }
        }

        /// <summary>
        /// The largest ball mass over body effective mass the law accepts (a body a trillion times lighter than the ball
        /// changes its velocity by about 1e-12 of it; a far lighter one overflows alpha (1 + m/M)).
        /// </summary>
        internal const double MaximumMassRatio = 1e12;

        /// <summary>
        /// The impact with a free rigid body whose centre of mass is offset from the contact point (<see cref="RigidImpact"/>):
        /// <paramref name="body"/> gives the surface's motion and the face normal (its effective mass is not used),
        /// <paramref name="inertia"/> the mass, lever and inertia. A body that cannot rotate under the impulse (zero lever
        /// or infinite moments) goes through <see cref="Resolve(Ball, in Vector3d, in Vector3d, in Vector3d, in ImpactBody, in ContactProperties)"/>
        /// with the effective mass <c>inertia.Mass</c>: today's numbers, bit for bit.
        /// </summary>
        /// <exception cref="ArgumentException">An argument is null or not finite, the body is the default value, or the contact has a
        /// normal-force offset (not part of the rigid-body law); the message names it.</exception>
        internal static ImpactOutcome Resolve(
            Ball ball, in Vector3d position, in Vector3d velocity, in Vector3d angularVelocity, in ImpactBody body, in RigidBodyInertia inertia,
            in ContactProperties contact)
        {
            if (inertia.IsPointMass)
            {
                var pointMass = new ImpactBody(body.Point, body.Velocity, body.AngularVelocity, body.Normal, inertia.Mass);
                return Resolve(ball, position, velocity, angularVelocity, pointMass, contact);
            }

            CheckArguments(ball, position, velocity, angularVelocity, body);

            if (contact.ForceOffset != 0 || contact.ForceOffsetPerSpeed != 0)
            {
                throw new ArgumentException("contact must have no normal-force offset (D = 0) for an impact with a rotating rigid body.", nameof(contact));
            }

            Vector3d n = body.Normal;
            Vector3d contactPoint = position - n * ball.Radius;
            Vector3d surfaceVelocity = body.SurfaceVelocityAt(contactPoint);
            Vector3d relative = velocity - surfaceVelocity;
            Vector3d v = velocity, w = angularVelocity;
            double up = 1;
            if (!IsModerate(relative, angularVelocity, ball.Radius))
            {
                // As the point-mass law's large path: the rigid law (no offset here) is linear in the velocities, so it is
                // solved at 2^-600 of them and its impulse scaled back.
                relative = velocity * ScaleDown - ScaledSurfaceVelocity(body, contactPoint);
                v = velocity * ScaleDown;
                w = angularVelocity * ScaleDown;
                up = ScaleUp;
            }

            RigidImpact.Resolve(ball.Mass, ball.Radius, ball.InertiaFactor, inertia, n, relative, w, contact,
                out Vector3d impulse, out BounceRegime regime, out double e, out double vn);
            if (regime == BounceRegime.None)
            {
                return new ImpactOutcome(velocity, angularVelocity, Vector3d.Zero, BounceRegime.None, 0, 0, Vector3d.Zero);
            }

            // up is 1 (exact) on the moderate path, so these are the unscaled formulas there, bit for bit.
            Vector3d velocity2 = (v + impulse * (1.0 / ball.Mass)) * up;
            Vector3d spin2 = (w - Vector3d.Cross(n, impulse) * (1.0 / (ball.InertiaFactor * ball.Mass * ball.Radius))) * up;
            impulse *= up;
            return new ImpactOutcome(velocity2, spin2, impulse, regime, e, vn * up, -inertia.Compliance(impulse));
        }

        /// <summary>
        /// The impact law in the body's (initial) frame: ball velocity <paramref name="v1"/> relative to the face,
        /// which is at rest there, mass ratio kappa = m/M. Returns the ball's relative velocity and spin after.
        /// Inputs are not checked (callers do). With kappa = 0 this is the ground bounce exactly.
        /// </summary>
        internal static void Resolve(
            double radius, double alpha, double kappa, in Vector3d n, in Vector3d v1, in Vector3d w1, in ContactProperties contact,
            out Vector3d v2, out Vector3d w2, out BounceRegime regime, out double ey, out double vn)
        {
            if (IsModerate(v1, w1, radius))
            {
                Resolve(radius, alpha, kappa, n, v1, w1, v1.Length, contact, out v2, out w2, out regime, out ey, out vn);
                return;
            }

            // Speeds beyond 2^500 m/s (3.3e150; also a spin, or its surface speed, beyond 2^500): products below ((1 + e) vn, alpha' R w,
            // the slide's friction term) could overflow and meet as infinity minus infinity. With the normal-force offset
            // taken at the true speed, the law is linear in the velocities (the restitution depends on the angle only), so it
            // is solved at 2^-600 of them and scaled back, exactly (powers of two): each result is finite, or infinite where
            // its true value is beyond a double, never NaN.
            Resolve(radius, alpha, kappa, n, v1 * ScaleDown, w1 * ScaleDown, Math.Min(v1.Length, double.MaxValue), contact,
                out v2, out w2, out regime, out ey, out vn);
            v2 *= ScaleUp;
            w2 *= ScaleUp;
            vn *= ScaleUp;
        }

        private const double MaximumFriction = 1e290;
        private const double LargeSpeed = 3.273390607896142e150; // 2^500
        private const double ScaleDown = 2.409919865102884e-181; // 2^-600
        private const double ScaleUp = 4.149515568880993e180; // 2^600

        // The law with the normal-force offset taken at incoming speed offsetSpeed (|v1| itself, unless v1 is scaled).
        private static void Resolve(
            double radius, double alpha, double kappa, in Vector3d n, in Vector3d v1, in Vector3d w1, double offsetSpeed, in ContactProperties contact,
            out Vector3d v2, out Vector3d w2, out BounceRegime regime, out double ey, out double vn)
        {
            vn = -Vector3d.Dot(v1, n);
            if (!(vn > 0))
            {
                v2 = v1;
                w2 = w1;
                regime = BounceRegime.None;
                ey = 0;
                vn = 0;
                return;
            }

            // alpha' = alpha (1 + kappa); multiplying by 1 + 0 = 1 is exact, so kappa = 0 is the ground bounce bit for bit.
            double onePlusKappa = 1 + kappa;
            double alphaEffective = alpha * onePlusKappa;

            Vector3d vt = v1 + n * vn;
            Vector3d spinNormal = n * Vector3d.Dot(w1, n);
            Vector3d omega = Vector3d.Cross(n, w1) * radius;
            Vector3d u1 = vt + omega;
            Vector3d lambda1 = vt - omega * alphaEffective;

            double tangentialSpeed = vt.Length;
            double incomingAngleDegrees = PortableMath.Atan2(vn, tangentialSpeed) * (180.0 / Math.PI);
            ey = contact.NormalRestitutionAt(incomingAngleDegrees);
            double normalChange = (1 + ey) * vn / onePlusKappa; // J: the ball's normal velocity change
            // Friction above 1e290 is taken as 1e290: a larger one would overflow (1 + alpha') mu (alpha' is at most
            // 1 + 1e12 here: an inertia factor of at most 1, a mass ratio of at most 1e12). Only a friction that large
            // changes (and only at a normal speed under about 1e-290 of the slip), where before it gave NaN.
            double mu = Math.Min(contact.Friction, MaximumFriction);

            // Normal-force offset: against the rolling direction, capped so it never outruns friction (energy)
            // and never reverses the rolling.
            double offset = Math.Min(contact.ForceOffsetAt(offsetSpeed), (1 + alphaEffective) * mu * radius * InverseSqrt2);
            double lambdaLength = lambda1.Length;
            double delta = Math.Min(offset * normalChange / radius * onePlusKappa, lambdaLength); // Lam' loses (1 + kappa) D J / R
            Vector3d offsetImpulse = lambdaLength > 0 ? lambda1 * (delta / lambdaLength) : Vector3d.Zero;
            Vector3d lambda2 = lambda1 - offsetImpulse;

            Vector3d u2;
            Vector3d offsetDirection = lambdaLength > 0 ? lambda1 / lambdaLength : Vector3d.Zero;
            double offsetRate = normalChange > 0 ? delta / normalChange / onePlusKappa : 0; // a: offset's share of the slip change per unit q
            if (Slides(u1, offsetDirection, offsetRate, (1 + alphaEffective) * mu, normalChange / alpha, out Vector3d slide))
            {
                u2 = slide;
                regime = BounceRegime.Slide;
            }
            else
            {
                // Gripped (or was rolling without slip from the start): the slip recoils to -e_x of its incoming value.
                u2 = u1 * -contact.TangentialRestitution;
                regime = BounceRegime.Grip;
            }

            double inverseOnePlusAlpha = 1.0 / (1 + alphaEffective);
            Vector3d relativeTangential2 = (lambda2 + u2 * alphaEffective) * inverseOnePlusAlpha;
            Vector3d omega2 = (u2 - lambda2) * inverseOnePlusAlpha;
            w2 = spinNormal - Vector3d.Cross(n, omega2) * (1.0 / radius);
            if (kappa > 0)
            {
                // Back from the relative tangential velocity to the ball's, in the body's initial frame: momentum is
                // shared with the body's contact point, vt2 = (v_r2 + kappa vt1)/(1 + kappa).
                Vector3d vt2 = (relativeTangential2 + vt * kappa) / onePlusKappa;
                v2 = vt2 + n * ((ey - kappa) * vn / onePlusKappa);
            }
            else
            {
                v2 = relativeTangential2 + n * (ey * vn);
            }
        }

        /// <summary>
        /// Follows the slip u of the contact point through the contact while it slides: with q the normal
        /// impulse per unit (alpha m) (0 to Q = J/alpha), du/dq = a e1 - b u/|u|, where a e1 is the offset
        /// torque's push (along the rolling direction e1) and b = (1 + alpha') mu the friction's. Returns false
        /// when the slip reaches zero before the end (the ball grips), else the final slip.
        /// </summary>
        /// <remarks>
        /// <para>When the slip is parallel to e1 (every bounce in a vertical plane) or there is no offset, the
        /// direction does not change and u2 = u1 + Q (a e1 - b s1): Cross's equations. Otherwise the slip
        /// turns toward e1 as it shrinks. Writing u = s (cos th, sin th) in the plane of e1 and u1, with
        /// t = tan(th/2) = r t0 and k = b/a &gt; 1 (the cap on D makes k &gt;= sqrt 2), the ODE integrates in closed
        /// form: s = s0 r^(k-1) (1 + t^2)/(1 + t0^2) and
        /// q(r) = s0/(a (1 + t0^2)) [(1 - r^(k-1))/(k-1) + t0^2 (1 - r^(k+1))/(k+1)]. The slip vanishes at r = 0,
        /// q* = s0/(a (1 + t0^2)) [1/(k-1) + t0^2/(k+1)]; if q* &gt; Q the ball slides throughout and r at q = Q is
        /// found by safeguarded Newton on that monotone function (at most 200 iterations). Since
        /// d|u|/dq = a cos th - b &lt; 0 the slip only ever shrinks, so a sliding impact cannot gain energy.</para>
        /// </remarks>
        private static bool Slides(in Vector3d u1, in Vector3d e1, double a, double b, double q, out Vector3d u2)
        {
            u2 = default;
            double s0 = u1.Length;
            if (!(s0 > 0))
            {
                return false; // rolling without slip already: it grips
            }

            Vector3d s1 = u1 / s0;
            double cosine = Vector3d.Dot(s1, e1);
            Vector3d across = s1 - e1 * cosine;
            double sine = across.Length;
            if (!(a > 0) || !(b > a) || sine <= 1e-12 || 1 + cosine <= 1e-9)
            {
                // The direction does not turn (or the turn is below rounding): Cross's straight-line slide.
                Vector3d straight = u1 + (e1 * a - s1 * b) * q;
                if (Vector3d.Dot(straight, s1) > 0)
                {
                    u2 = straight;
                    return true;
                }

                return false;
            }

            Vector3d e2 = across / sine;
            double t0 = sine / (1 + cosine);
            double t0Squared = t0 * t0;
            double k = b / a;
            double scale = s0 / (a * (1 + t0Squared));
            double stopAt = scale * (1 / (k - 1) + t0Squared / (k + 1));
            if (!(stopAt > q))
            {
                return false;
            }

            // Solve q(r) = Q for r in (0, 1): the impulse needed to shrink the slip to r rises from 0 at r = 1 to
            // q* at r = 0, so g(r) = q(r) - Q falls from q* - Q > 0 at r = 0 to -Q < 0 at r = 1.
            double lo = 0, hi = 1, r = 0.5;
            for (int i = 0; i < 200; i++)
            {
                double rk1 = PortableMath.Pow(r, k - 1);
                double rk = rk1 * r;
                double g = scale * ((1 - rk1) / (k - 1) + t0Squared * (1 - rk * r) / (k + 1)) - q;
                if (g > 0)
                {
                    lo = r;
                }
                else
                {
                    hi = r;
                }

                if (g == 0 || hi - lo <= 1e-16)
                {
                    break;
                }

                double slope = -scale * (rk1 / r + t0Squared * rk);
                double newton = slope < 0 ? r - g / slope : double.NaN;
                double next = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
                if (Math.Abs(next - r) <= 1e-16)
                {
                    r = next;
                    break;
                }

                r = next;
            }

            double t = r * t0;
            double tSquared = t * t;
            double s = s0 * PortableMath.Pow(r, k - 1) * (1 + tSquared) / (1 + t0Squared);
            double cos2 = (1 - tSquared) / (1 + tSquared);
            double sin2 = 2 * t / (1 + tSquared);
            u2 = (e1 * cos2 + e2 * sin2) * s;
            return true;
        }
    }
}
