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
    /// slide: du/dq = a Lam_hat1 - b u/|u| for q from 0 to (1 + e_y) vn / alpha, with a = delta / ((1 + e_y) vn)
    ///        and b = (1 + alpha) mu; when u1 is parallel to Lam1 this is
    ///        u2 = u1 + (delta Lam_hat1 - (1 + alpha) mu (1 + e_y) vn s_hat1) / alpha,  s_hat1 = u1/|u1|,
    ///        valid while u2 . s_hat1 &gt; 0 (Cross's vx2 &gt; R w2); the ball slides throughout if |u| stays &gt; 0
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
    /// <item><description>Sliding friction acts against the slip throughout. When the offset torque is not parallel
    /// to the slip (sidespin), the slip turns toward the rolling direction as it shrinks; that path is
    /// followed exactly (closed form, see <c>Slides</c>), and the ball grips if the slip reaches zero before the
    /// end of the contact. In a vertical plane it reduces to Cross's straight-line slide, with the test
    /// vx2 &gt; R w2.</description></item>
    /// <item><description>Spin about the normal, (w . n) n, is kept apart: a point contact's friction exerts no
    /// torque about the normal, so it passes through unchanged. Spin about the direction of travel
    /// (a tilted side-spin axis) moves the contact point sideways and deflects the bounce.</description></item>
    /// </list>
    /// <para>The computation is <see cref="Impact"/>'s general law for a ball hitting a body of finite effective mass,
    /// with the ground as an immovable body at rest (mass ratio 0): the same numbers, bit for bit, as this class gave
    /// before that law existed.</para>
    /// <para>Energy: the tangential kinetic energy is m/2 (|Lam|^2 + alpha |u|^2)/(1 + alpha). Neither |Lam| nor
    /// |u| grows (d|u|/dq = a cos - b &lt; 0 while sliding), and e_y, e_x are at most 1, so no bounce gains energy.</para>
    /// </remarks>
    public sealed class CrossBounce : IBounceModel
    {
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

            // The ground is an immovable body at rest, so its frame is the caller's and kappa = m/M = 0: the general
            // impact law then performs exactly the operations of Cross's bounce (tests/.../ImpactLawTests check it bit for bit).
            Vector3d n = normal.NormalizedOrZero();
            Impact.Resolve(ball.Radius, ball.InertiaFactor, 0, n, velocity, angularVelocity, Surface.Contact,
                out Vector3d velocity2, out Vector3d spin2, out BounceRegime regime, out double ey, out double vn);
            return new BounceOutcome(velocity2, spin2, regime, ey, vn);
        }

        /// <inheritdoc />
        public override string ToString() => $"CrossBounce({Surface})";
    }
}
