using System;
using MagnusBall;
using MagnusBall.Contact;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// A frozen copy of CrossBounce as it was before the general impact law (commit 1bbd672), kept as the reference the
    /// refactored bounce must match bit for bit. Do not edit.
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
    /// <para>Energy: the tangential kinetic energy is m/2 (|Lam|^2 + alpha |u|^2)/(1 + alpha). Neither |Lam| nor
    /// |u| grows (d|u|/dq = a cos - b &lt; 0 while sliding), and e_y, e_x are at most 1, so no bounce gains energy.</para>
    /// </remarks>
    internal sealed class ReferenceCrossBounce : IBounceModel
    {
        private static readonly double InverseSqrt2 = 1.0 / Math.Sqrt(2.0);

        /// <summary>Creates the model for a surface.</summary>
        /// <param name="surface">The surface's contact parameters; not null.</param>
        /// <exception cref="ArgumentNullException">surface is null.</exception>
        public ReferenceCrossBounce(Surface surface)
        {
            Surface = surface ?? throw new ArgumentNullException(nameof(surface));
        }

        /// <summary>The surface.</summary>
        public Surface Surface { get; }

        /// <inheritdoc />
        public BounceOutcome Bounce(Ball ball, in Vector3d normal, in Vector3d velocity, in Vector3d angularVelocity)
        {

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
            double incomingAngleDegrees = PortableMath.Atan2(vn, tangentialSpeed) * (180.0 / Math.PI);
            double ey = surface.Contact.NormalRestitutionAt(incomingAngleDegrees);
            double normalChange = (1 + ey) * vn; // |Delta v_n| = P_n / m
            double mu = surface.Contact.Friction;

            // Normal-force offset: against the rolling direction, capped so it never outruns friction (energy)
            // and never reverses the rolling.
            double offset = Math.Min(surface.Contact.ForceOffsetAt(velocity.Length), (1 + alpha) * mu * radius * InverseSqrt2);
            double lambdaLength = lambda1.Length;
            double delta = Math.Min(offset * normalChange / radius, lambdaLength);
            Vector3d offsetImpulse = lambdaLength > 0 ? lambda1 * (delta / lambdaLength) : Vector3d.Zero;
            Vector3d lambda2 = lambda1 - offsetImpulse;

            Vector3d u2;
            BounceRegime regime;
            Vector3d offsetDirection = lambdaLength > 0 ? lambda1 / lambdaLength : Vector3d.Zero;
            double offsetRate = normalChange > 0 ? delta / normalChange : 0; // a: offset's share of the slip change per unit q
            if (Slides(u1, offsetDirection, offsetRate, (1 + alpha) * mu, normalChange / alpha, out Vector3d slide))
            {
                u2 = slide;
                regime = BounceRegime.Slide;
            }
            else
            {
                // Gripped (or was rolling without slip from the start): the slip recoils to -e_x of its incoming value.
                u2 = u1 * -surface.Contact.TangentialRestitution;
                regime = BounceRegime.Grip;
            }

            double inverseOnePlusAlpha = 1.0 / (1 + alpha);
            Vector3d vt2 = (lambda2 + u2 * alpha) * inverseOnePlusAlpha;
            Vector3d omega2 = (u2 - lambda2) * inverseOnePlusAlpha;
            Vector3d spin2 = spinNormal - Vector3d.Cross(n, omega2) * (1.0 / radius);
            Vector3d velocity2 = vt2 + n * (ey * vn);
            return new BounceOutcome(velocity2, spin2, regime, ey, vn);
        }

        /// <summary>
        /// Follows the slip u of the contact point through the contact while it slides: with q the normal
        /// impulse per unit (alpha m) (0 to Q = J/alpha), du/dq = a e1 - b u/|u|, where a e1 is the offset
        /// torque's push (along the rolling direction e1) and b = (1 + alpha) mu the friction's. Returns false
        /// when the slip reaches zero before the end (the ball grips), else the final slip.
        /// </summary>
        /// <remarks>
        /// <para>When the slip is parallel to e1 (every bounce in a vertical plane) or there is no offset, the
        /// direction does not change and u2 = u1 + Q (a e1 - b s1): Cross's equations. Otherwise the slip
        /// turns toward e1 as it shrinks. Writing u = s (cos th, sin th) in the plane of e1 and u1, with
        /// t = tan(th/2) = r t0 and k = b/a &gt; 1 (the cap on D makes k &gt;= sqrt 2), the ODE integrates in closed
        /// form (worked out here): s = s0 r^(k-1) (1 + t^2)/(1 + t0^2) and
        /// q(r) = s0/(a (1 + t0^2)) [(1 - r^(k-1))/(k-1) + t0^2 (1 - r^(k+1))/(k+1)]. The slip vanishes at r = 0,
        /// q* = s0/(a (1 + t0^2)) [1/(k-1) + t0^2/(k+1)]; if q* &gt; Q the ball slides throughout and r at q = Q is
        /// found by safeguarded Newton on that monotone function. Since d|u|/dq = a cos th - b &lt; 0 the slip
        /// only ever shrinks, so a sliding bounce cannot gain energy.</para>
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

        /// <inheritdoc />
        public override string ToString() => $"ReferenceCrossBounce({Surface})";
    }
}
