using System;

namespace MagnusBall.Contact
{
    /// <summary>
    /// How a rigid body answers an impulse at the contact point: its mass, the lever from its centre of mass to the
    /// contact point, and its inverse inertia about its centre of mass as three principal moments along three
    /// orthonormal axes (any frame: the axes are vectors). A point mass is the case of a zero lever or infinite moments.
    /// </summary>
    internal readonly struct RigidBodyInertia
    {
        internal readonly double Mass;
        internal readonly Vector3d Lever;      // r: from the centre of mass to the contact point, m
        internal readonly Vector3d Axis1, Axis2, Axis3;
        internal readonly double InverseMoment1, InverseMoment2, InverseMoment3; // 1/I, 1/(kg m^2); 0 for an infinite moment

        /// <param name="mass">kg, finite and &gt; 0.</param>
        /// <param name="lever">From the centre of mass to the contact point, m; finite.</param>
        /// <param name="axis1">First principal axis (unit); the other two are made orthonormal to it from <paramref name="axis2"/>.</param>
        /// <param name="axis2">Second principal axis, not parallel to the first.</param>
        /// <param name="moment1">Principal moment about axis 1, kg m^2: &gt; 0 or positive infinity.</param>
        /// <param name="moment2">About axis 2.</param>
        /// <param name="moment3">About axis 3 = axis1 x axis2.</param>
        internal RigidBodyInertia(double mass, in Vector3d lever, in Vector3d axis1, in Vector3d axis2, double moment1, double moment2, double moment3)
        {
            Mass = Require.Positive(mass, nameof(mass));
            Lever = Require.Finite(lever, nameof(lever));
            Axis1 = Require.NonZero(axis1, nameof(axis1)).NormalizedOrZero();
            Vector3d a2 = Require.NonZero(axis2, nameof(axis2));
            a2 = a2 - Axis1 * Vector3d.Dot(a2, Axis1);
            if (!(a2.Length > 1e-9))
            {
                throw new ArgumentException("axis2 must not be parallel to axis1.", nameof(axis2));
            }

            Axis2 = a2.NormalizedOrZero();
            Axis3 = Vector3d.Cross(Axis1, Axis2);
            InverseMoment1 = InverseMoment(moment1, nameof(moment1));
            InverseMoment2 = InverseMoment(moment2, nameof(moment2));
            InverseMoment3 = InverseMoment(moment3, nameof(moment3));
        }

        /// <summary>True when the body cannot rotate under an impulse at the contact (zero lever, or infinite moments): a point mass.</summary>
        internal bool IsPointMass =>
            Lever.LengthSquared == 0 || (InverseMoment1 == 0 && InverseMoment2 == 0 && InverseMoment3 == 0);

        /// <summary>The angular velocity change of the body for an angular impulse <paramref name="angularImpulse"/> about its centre of mass: I^-1 L.</summary>
        internal Vector3d InverseInertia(in Vector3d angularImpulse) =>
            Axis1 * (InverseMoment1 * Vector3d.Dot(Axis1, angularImpulse))
            + Axis2 * (InverseMoment2 * Vector3d.Dot(Axis2, angularImpulse))
            + Axis3 * (InverseMoment3 * Vector3d.Dot(Axis3, angularImpulse));

        /// <summary>
        /// The velocity change of the body's material point at the contact when the ball receives
        /// <paramref name="impulseOnBall"/> (the body receives minus it), with the sign reversed: K_body P =
        /// P/M + (I^-1 (r x P)) x r. This is the body's share of the contact's inverse effective mass matrix.
        /// </summary>
        internal Vector3d Compliance(in Vector3d impulseOnBall) =>
            impulseOnBall * (1.0 / Mass) + Vector3d.Cross(InverseInertia(Vector3d.Cross(Lever, impulseOnBall)), Lever);

        private static double InverseMoment(double moment, string name)
        {
            if (double.IsPositiveInfinity(moment))
            {
                return 0;
            }

            return 1.0 / Require.Positive(moment, name);
        }
    }

    /// <summary>
    /// The impact of a spinning ball with a free rigid body whose centre of mass is offset from the contact point:
    /// the contact's inverse effective mass is the 3 x 3 matrix K = K_ball + (1/M) 1 + [r x]^T I^-1 [r x], so the
    /// normal and tangential impulses couple through the body's rotation. Newton's COR sets the normal relative
    /// velocity after; Cross's slide/grip contact (no normal-force offset) sets the tangential part:
    /// grip when the impulse that ends the slip lies inside the friction cone (the final slip then recoils to -e_x of
    /// its incoming value), else a slide along the incoming slip direction with friction mu times the normal impulse.
    /// With K isotropic along the face and uncoupled (a point mass) this is <see cref="Impact"/>'s law.
    /// Where the coupling is strong enough that this would create energy, or a slide would push the slip past zero
    /// (bodies far from any club head, or a nearly frictionless face well off the path), the impulse is taken in two
    /// dissipative steps instead (normal, then tangential; see Sequential). Allocation-free; inputs are not checked (callers do).
    /// </summary>
    internal static class RigidImpact
    {
        /// <summary>
        /// The law in the frame of the body's contact point (the face at rest there): ball centre velocity
        /// <paramref name="v1"/>, spin <paramref name="w1"/>. Returns the impulse on the ball (zero and regime None
        /// when the ball is not approaching the face).
        /// </summary>
        internal static void Resolve(
            double mass, double radius, double alpha, in RigidBodyInertia body, in Vector3d n, in Vector3d v1, in Vector3d w1,
            in ContactProperties contact, out Vector3d impulse, out BounceRegime regime, out double ey, out double vn)
            => Resolve(mass, radius, alpha, body, n, v1, w1, contact, out impulse, out regime, out ey, out vn, out _);

        /// <summary>As above; <paramref name="coupled"/> tells whether the coupled solution stood (false: the two-step fallback, or no impact).</summary>
        internal static void Resolve(
            double mass, double radius, double alpha, in RigidBodyInertia body, in Vector3d n, in Vector3d v1, in Vector3d w1,
            in ContactProperties contact, out Vector3d impulse, out BounceRegime regime, out double ey, out double vn, out bool coupled)
        {
            coupled = false;
            vn = -Vector3d.Dot(v1, n);
            if (!(vn > 0))
            {
                impulse = Vector3d.Zero;
                regime = BounceRegime.None;
                ey = 0;
                vn = 0;
                return;
            }

            Vector3d vt = v1 + n * vn;
            Vector3d u1 = v1 + Vector3d.Cross(n, w1) * radius; // the contact point's velocity, = v + w x (-R n)
            Vector3d slip = u1 - n * Vector3d.Dot(u1, n);
            double slipSpeed = slip.Length;
            double incomingAngleDegrees = PortableMath.Atan2(vn, vt.Length) * (180.0 / Math.PI);
            ey = contact.NormalRestitutionAt(incomingAngleDegrees);

            // An orthonormal contact basis: n, t1 along the slip (any direction across n if there is none), t2.
            Vector3d t1 = slipSpeed > 0 ? slip / slipSpeed : AnyAcross(n);
            Vector3d t2 = Vector3d.Cross(n, t1);

            // K in that basis: K P = K_ball P + K_body P, K_ball = (1/m) [1 + (1/alpha)(1 - n n^T)].
            Vector3d kn = Apply(mass, alpha, body, n, n);
            Vector3d k1 = Apply(mass, alpha, body, n, t1);
            Vector3d k2 = Apply(mass, alpha, body, n, t2);
            double a = Vector3d.Dot(n, kn), b = Vector3d.Dot(n, k1), c = Vector3d.Dot(n, k2);
            double d = Vector3d.Dot(t1, k1), f = Vector3d.Dot(t1, k2), g = Vector3d.Dot(t2, k2);

            // Scale K to a largest diagonal entry of 1 (the impulses come out in kg times that scale) so that Cramer's
            // products cannot overflow for a very light or very compliant body.
            double scale = 1.0 / Math.Max(a, Math.Max(d, g));
            a *= scale;
            b *= scale;
            c *= scale;
            d *= scale;
            f *= scale;
            g *= scale;

            // The impulse that ends the slip: K P = (1 + e) vn n - slip.
            double mu = contact.Friction;
            double recoil = (1 + contact.TangentialRestitution) * slipSpeed;
            Solve(a, b, c, d, f, g, (1 + ey) * vn, -slipSpeed, 0, out double pn, out double p1, out double p2);
            if (slipSpeed == 0 || p1 * p1 + p2 * p2 <= mu * mu * pn * pn)
            {
                // Grip: the slip recoils to -e_x of its incoming value.
                Solve(a, b, c, d, f, g, (1 + ey) * vn, -recoil, 0, out pn, out p1, out p2);
                regime = BounceRegime.Grip;
            }
            else
            {
                // Slide: P = Pn (n - mu t1), Pn from the normal condition n.K P = (1 + e) vn, denominator a - mu b.
                double denominator = a - mu * b;
                pn = denominator > 1e-12 ? (1 + ey) * vn / denominator : double.PositiveInfinity;
                p1 = -mu * pn;
                p2 = 0;
                regime = BounceRegime.Slide;
            }

            // The coupled solution stands unless the coupling is strong enough to break it: it would create energy
            // (Newton's COR with a coupled K can), a slide would reverse the slip (friction pushing past zero slip), or the
            // slide's normal impulse has no finite solution (a friction jam). Then the impulse is taken in two steps that
            // each dissipate energy (Sequential). No club head comes near this (RigidHeadImpactTests counts it).
            coupled = double.IsFinite(pn) && pn > 0;
            if (coupled)
            {
                double kp0 = a * pn + b * p1 + c * p2, kp1 = b * pn + d * p1 + f * p2, kp2 = c * pn + f * p1 + g * p2;
                double work = -pn * vn + p1 * slipSpeed; // P . u1 in the scaled basis
                double energyChange = work + 0.5 * (pn * kp0 + p1 * kp1 + p2 * kp2);
                bool reverses = regime == BounceRegime.Slide && slipSpeed + kp1 < 0;
                coupled = !reverses && energyChange <= 1e-12 * Math.Abs(work);
            }

            if (!coupled)
            {
                Sequential(a, b, c, d, f, g, vn, slipSpeed, ey, mu, contact.TangentialRestitution, out pn, out p1, out p2, out regime);
            }

            impulse = (n * pn + t1 * p1 + t2 * p2) * scale;
        }

        /// <summary>
        /// The two-step impulse for a strongly coupled contact, in the scaled basis (n, t1, t2): first a frictionless
        /// normal impulse (1 + e) vn / K_nn, which dissipates (1 - e^2) of the normal energy; then the tangential
        /// impulse for the slip it leaves, -(1 + e_x) K_tt^-1 u' if the zero-slip impulse K_tt^-1 u' lies inside the friction
        /// cone, else mu P_n along it (either dissipates: it is a fraction s in [0, 2] of the slip-ending impulse in K's
        /// metric); last, if the ball would still approach the face, a plastic normal impulse stops it (dissipates too).
        /// With an uncoupled K (a point mass) it is Cross's law.
        /// </summary>
        private static void Sequential(
            double a, double b, double c, double d, double f, double g, double vn, double slipSpeed, double ey, double mu, double ex,
            out double pn, out double p1, out double p2, out BounceRegime regime)
        {
            pn = (1 + ey) * vn / a;
            double u1 = slipSpeed + b * pn, u2 = c * pn; // the slip after the normal step
            double inverseDeterminant = 1.0 / (d * g - f * f);
            double z1 = (g * u1 - f * u2) * inverseDeterminant, z2 = (d * u2 - f * u1) * inverseDeterminant; // K_tt^-1 u'
            double length = Math.Sqrt(z1 * z1 + z2 * z2);
            if (length <= mu * pn)
            {
                p1 = -(1 + ex) * z1;
                p2 = -(1 + ex) * z2;
                regime = BounceRegime.Grip;
            }
            else
            {
                double s = mu * pn / length;
                p1 = -s * z1;
                p2 = -s * z2;
                regime = BounceRegime.Slide;
            }

            double separating = -vn + a * pn + b * p1 + c * p2;
            if (separating < 0)
            {
                pn -= separating / a;
            }
        }

        /// <summary>K x for an impulse x on the ball: the ball's (1/m)[x + (1/alpha)(x - n (n.x))] plus the body's.</summary>
        private static Vector3d Apply(double mass, double alpha, in RigidBodyInertia body, in Vector3d n, in Vector3d x)
        {
            Vector3d across = x - n * Vector3d.Dot(n, x);
            return (x + across * (1.0 / alpha)) * (1.0 / mass) + body.Compliance(x);
        }

        /// <summary>Solves the symmetric positive-definite system [[a b c][b d f][c f g]] x = r by Cramer's rule.</summary>
        private static void Solve(double a, double b, double c, double d, double f, double g, double r0, double r1, double r2,
            out double x0, out double x1, out double x2)
        {
            double c00 = d * g - f * f, c01 = c * f - b * g, c02 = b * f - c * d;
            double c11 = a * g - c * c, c12 = b * c - a * f, c22 = a * d - b * b;
            double inverseDeterminant = 1.0 / (a * c00 + b * c01 + c * c02);
            x0 = (c00 * r0 + c01 * r1 + c02 * r2) * inverseDeterminant;
            x1 = (c01 * r0 + c11 * r1 + c12 * r2) * inverseDeterminant;
            x2 = (c02 * r0 + c12 * r1 + c22 * r2) * inverseDeterminant;
        }

        private static Vector3d AnyAcross(in Vector3d n)
        {
            Vector3d helper = Math.Abs(n.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY;
            return Vector3d.Cross(n, helper).NormalizedOrZero();
        }
    }
}
