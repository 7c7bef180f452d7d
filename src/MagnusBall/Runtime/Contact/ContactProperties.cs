using System;

namespace MagnusBall.Contact
{
    /// <summary>
    /// The contact parameters of one impact, as a value: the normal coefficient of restitution e = e0 - k theta
    /// (clamped to [0, 1]), the sliding friction coefficient mu, the tangential restitution e_x of a ball that
    /// grips, and the normal-force offset D = D0 + D1 v. The same numbers a <see cref="Surface"/> holds
    /// (<see cref="Surface.Contact"/>), for impacts whose parameters are computed per hit (a racket's impact
    /// point, a club's face) without allocating.
    /// </summary>
    public readonly struct ContactProperties
    {
        /// <summary>e0: the normal coefficient of restitution at grazing incidence (the relative velocity's angle to the face is 0).</summary>
        public readonly double NormalRestitution;

        /// <summary>k in e = e0 - k theta, per degree of the relative incoming angle from the face.</summary>
        public readonly double NormalRestitutionPerDegree;

        /// <summary>mu: the sliding friction coefficient.</summary>
        public readonly double Friction;

        /// <summary>e_x: the tangential coefficient of restitution of a ball that grips (its slip reverses to -e_x of the incoming slip).</summary>
        public readonly double TangentialRestitution;

        /// <summary>D0: the speed-independent part of the normal-force offset, m.</summary>
        public readonly double ForceOffset;

        /// <summary>D1: the normal-force offset per unit relative incoming speed, s (D = D0 + D1 v).</summary>
        public readonly double ForceOffsetPerSpeed;

        /// <summary>Creates contact parameters.</summary>
        /// <param name="normalRestitution">e0, the normal COR; in [0, 1].</param>
        /// <param name="friction">mu, the sliding friction coefficient; finite and &gt;= 0.</param>
        /// <param name="tangentialRestitution">e_x, the tangential COR in grip; in [0, 1].</param>
        /// <param name="forceOffset">D0, m; finite and &gt;= 0.</param>
        /// <param name="normalRestitutionPerDegree">k in e = e0 - k theta, per degree; finite (the result is clamped to [0, 1]).</param>
        /// <param name="forceOffsetPerSpeed">D1, s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">A value is outside its range; the message names it.</exception>
        public ContactProperties(
            double normalRestitution,
            double friction,
            double tangentialRestitution = 0,
            double forceOffset = 0,
            double normalRestitutionPerDegree = 0,
            double forceOffsetPerSpeed = 0)
        {
            NormalRestitution = Require.InRange(normalRestitution, 0, 1, nameof(normalRestitution));
            Friction = Require.NonNegative(friction, nameof(friction));
            TangentialRestitution = Require.InRange(tangentialRestitution, 0, 1, nameof(tangentialRestitution));
            ForceOffset = Require.NonNegative(forceOffset, nameof(forceOffset));
            NormalRestitutionPerDegree = Require.Finite(normalRestitutionPerDegree, nameof(normalRestitutionPerDegree));
            ForceOffsetPerSpeed = Require.NonNegative(forceOffsetPerSpeed, nameof(forceOffsetPerSpeed));
        }

        /// <summary>The normal COR e0 - k theta for a relative incoming angle, clamped to [0, 1].</summary>
        /// <param name="incomingAngleDegrees">theta: the relative incoming velocity's angle from the face, degrees, in [0, 90].</param>
        internal double NormalRestitutionAt(double incomingAngleDegrees)
        {
            double e = NormalRestitution - NormalRestitutionPerDegree * incomingAngleDegrees;
            return e < 0 ? 0 : e > 1 ? 1 : e;
        }

        /// <summary>The normal-force offset D0 + D1 v for a relative incoming speed, m.</summary>
        /// <param name="incomingSpeed">v: the ball's speed relative to the face before the impact, m/s.</param>
        internal double ForceOffsetAt(double incomingSpeed) => ForceOffset + ForceOffsetPerSpeed * incomingSpeed;

        /// <inheritdoc />
        public override string ToString() =>
            $"ContactProperties(e={NormalRestitution:R}-{NormalRestitutionPerDegree:R}*theta, mu={Friction:R}, e_x={TangentialRestitution:R}, D={ForceOffset:R}+{ForceOffsetPerSpeed:R}*v)";
    }
}
