using System;

namespace MagnusBall.Contact
{
    /// <summary>
    /// The slide/grip bounce of a spinning ball after Cross (2002, "Grip-slip behavior of a bouncing ball",
    /// Am. J. Phys. 70; 2005, "Bounce of a spinning ball near normal incidence", Am. J. Phys. 73;
    /// 2020, Sports Eng. 23:9) and Brody, written in 3D for a surface of any orientation. The default contact
    /// model of the library. Immutable and thread-safe; a bounce allocates nothing.
    /// </summary>
    /// <remarks>
    /// <para><b>Cross's 2D model</b> (x along the surface, y normal, topspin w &gt; 0, I = alpha m R^2): the
    /// normal velocity reverses to e_y vy1. If the ball slides throughout,
    /// vx2 = vx1 - mu (1 + e_y) vy1 and w2 = w1 + (1 + e_y)(mu - D/R) vy1 / (alpha R), valid while
    /// vx2 &gt; R w2 at the end. Otherwise it grips: vx2 - R w2 = -e_x (vx1 - R w1), with the angular
    /// momentum about the contact point conserved apart from the offset torque of the normal force,
    /// m R vx2 + I w2 = m R vx1 + I w1 - m D (1 + e_y) vy1.</para>
    /// <para><b>In 3D</b>, with unit normal n (out of the surface), the contact point at -R n from the centre and
    /// the standard cross product (so no handedness is assumed: in a left-handed frame the angular velocity is
    /// in that frame's own left-hand convention and every product below keeps its physical meaning):</para>
    /// <code>
    /// vn    = -v1 . n                       approach speed (no bounce unless &gt; 0)
    /// vt    = v1 + vn n                     tangential velocity
    /// Omega = R (n x w1)                    tangential velocity of the contact point due to spin (= -R w in 2D)
    /// u     = vt + Omega                    slip of the contact point, v + w x (-R n), tangential part
    /// Lam   = vt - alpha Omega              angular momentum about the contact point / (m R), turned into the
    ///                                       tangent plane (= vx + alpha R w in 2D); the ball rolls along it
    /// </code>
    /// <para>A friction impulse F (tangential) changes u by (1 + alpha) F / (alpha m) and leaves Lam alone
    /// (it acts at the contact point). The offset torque of the normal force changes Lam by
    /// -delta Lam_hat and u by +delta Lam_hat / alpha, with delta = D (1 + e_y) vn / R. Then</para>
    /// <code>
    /// Lam2 = Lam1 - delta Lam_hat1
    /// slide: u2 = u1 + (delta Lam_hat1 - (1 + alpha) mu (1 + e_y) vn s_hat1) / alpha,  s_hat1 = u1/|u1|,
    ///        valid while u2 . s_hat1 &gt; 0 (the 3D form of vx2 &gt; R w2)
    /// grip:  u2 = -e_x u1
    /// vt2 = (Lam2 + alpha u2) / (1 + alpha),  Omega2 = (u2 - Lam2) / (1 + alpha),  w2 = -(n x Omega2)/R + (w1 . n) n
    /// v2  = vt2 + e_y vn n
    /// </code>
    /// <para>For a bounce in a vertical plane these are exactly Cross's equations. Choices made here for 3D,
    /// none of which changes a bounce in which the ball moves forward and rolls forward:</para>
    /// <list type="bullet">
    /// <item><description>The offset D resists rolling, so it acts against Lam (the direction the ball rolls in), and
    /// delta is capped at |Lam1|: it can stop the rolling, never reverse it. This makes the bounce continuous
    /// as the incoming tangential speed goes to zero (a vertical drop gets no offset torque).</description></item>
    /// <item><description>D is capped at (1 + alpha) mu R / sqrt(2), so the offset torque never outruns friction
    /// and a sliding bounce cannot gain energy (on the presets with a tennis ball the cap binds only above
    /// 88 m/s on the hard court); on a frictionless surface D is 0.</description></item>
    /// <item><description>As in Cross's model, sliding friction acts against the initial slip direction throughout.
    /// When the offset torque is not parallel to the slip (sidespin), the true slip would turn slightly
    /// during contact; this is not followed.</description></item>
    /// <item><description>Spin about the normal, (w . n) n, is kept apart: a point contact's friction exerts no
    /// torque about the normal, so it passes through unchanged. Spin about the direction of travel
    /// (a tilted side-spin axis) moves the contact point sideways and deflects the bounce.</description></item>
    /// </list>
    /// <para>Energy: the tangential kinetic energy is m/2 (|Lam|^2 + alpha |u|^2)/(1 + alpha). Neither |Lam| nor
    /// |u| grows, and e_y, e_x are at most 1, so no bounce gains energy.</para>
    /// </remarks>
    public sealed class CrossBounce : IBounceModel
    {
        private static readonly double InverseSqrt2 = 1.0 / Math.Sqrt(2.0);

        /// <summary>Creates the model for a surface.</summary>
        /// <param name="surface">The surface's contact parameters; not null.</param>
        /// <exception cref="ArgumentNullException">surface is null.</exception>
        public CrossBounce(Surface surface)
        {
            Surface = Require.NotNull(surface, nameof(surface));
        }

        /// <summary>The surface.</summary>
        public Surface Surface { get; }

        /// <summary>The Cross bounce on <see cref="Contact.Surface.Hard"/>.</summary>
        public static CrossBounce Hard { get; } = new CrossBounce(Surface.Hard);

        /// <summary>The Cross bounce on <see cref="Contact.Surface.Clay"/>.</summary>
        public static CrossBounce Clay { get; } = new CrossBounce(Surface.Clay);

        /// <summary>The Cross bounce on <see cref="Contact.Surface.Grass"/>.</summary>
        public static CrossBounce Grass { get; } = new CrossBounce(Surface.Grass);

        /// <summary>The Cross bounce on <see cref="Contact.Surface.Frictionless"/>.</summary>
        public static CrossBounce Frictionless { get; } = new CrossBounce(Surface.Frictionless);

        /// <inheritdoc />
        public BounceOutcome Bounce(Ball ball, in Vector3d normal, in Vector3d velocity, in Vector3d angularVelocity)
        {
            Require.NotNull(ball, nameof(ball));
            Require.NonZero(normal, nameof(normal));
            Require.Finite(velocity, nameof(velocity));
            Require.Finite(angularVelocity, nameof(angularVelocity));

            Vector3d n = normal.NormalizedOrZero();
            double vn = -Vector3d.Dot(velocity, n);
            if (!(vn > 0))
            {
                return new BounceOutcome(velocity, angularVelocity, BounceRegime.None, 0, 0);
            }

            double radius = ball.Radius;
            double alpha = ball.InertiaFactor;
            Surface surface = Surface;

            Vector3d vt = velocity + n * vn;
            Vector3d spinNormal = n * Vector3d.Dot(angularVelocity, n);
            Vector3d omega = Vector3d.Cross(n, angularVelocity) * radius;
            Vector3d u1 = vt + omega;
            Vector3d lambda1 = vt - omega * alpha;

            double tangentialSpeed = vt.Length;
            double incomingAngleDegrees = Math.Atan2(vn, tangentialSpeed) * (180.0 / Math.PI);
            double ey = surface.NormalRestitutionAt(incomingAngleDegrees);
            double normalChange = (1 + ey) * vn; // |Delta v_n| = P_n / m
            double mu = surface.SlidingFriction;

            // Normal-force offset: against the rolling direction, capped so it never outruns friction (energy)
            // and never reverses the rolling.
            double offset = Math.Min(surface.ForceOffsetAt(velocity.Length), (1 + alpha) * mu * radius * InverseSqrt2);
            double lambdaLength = lambda1.Length;
            double delta = Math.Min(offset * normalChange / radius, lambdaLength);
            Vector3d offsetImpulse = lambdaLength > 0 ? lambda1 * (delta / lambdaLength) : Vector3d.Zero;
            Vector3d lambda2 = lambda1 - offsetImpulse;

            double slip = u1.Length;
            Vector3d u2;
            BounceRegime regime;
            if (slip > 0)
            {
                Vector3d slipDirection = u1 / slip;
                Vector3d slide = u1 + (offsetImpulse - slipDirection * ((1 + alpha) * mu * normalChange)) / alpha;
                if (Vector3d.Dot(slide, slipDirection) > 0)
                {
                    u2 = slide;
                    regime = BounceRegime.Slide;
                }
                else
                {
                    u2 = u1 * -surface.TangentialRestitution;
                    regime = BounceRegime.Grip;
                }
            }
            else
            {
                // Already rolling without slip: it grips from the start.
                u2 = Vector3d.Zero;
                regime = BounceRegime.Grip;
            }

            double inverseOnePlusAlpha = 1.0 / (1 + alpha);
            Vector3d vt2 = (lambda2 + u2 * alpha) * inverseOnePlusAlpha;
            Vector3d omega2 = (u2 - lambda2) * inverseOnePlusAlpha;
            Vector3d spin2 = spinNormal - Vector3d.Cross(n, omega2) * (1.0 / radius);
            Vector3d velocity2 = vt2 + n * (ey * vn);
            return new BounceOutcome(velocity2, spin2, regime, ey, vn);
        }

        /// <inheritdoc />
        public override string ToString() => $"CrossBounce({Surface})";
    }
}
