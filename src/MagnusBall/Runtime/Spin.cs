using System;

namespace MagnusBall
{
    /// <summary>
    /// Builds angular velocities by the effect they have on the flight, not by an axis, so the same call
    /// gives the right spin in a right-handed z-up frame, Unity's left-handed y-up frame or Godot's
    /// right-handed y-up frame. Also converts spin-rate units to rad/s.
    /// </summary>
    /// <remarks>
    /// The Magnus force points along w x v. For unit, perpendicular v and d, (v x d) x v = d in any
    /// handedness (it is the vector triple-product identity, which uses only dot products), so
    /// w = n normalize(v x d) is the spin that curves the ball toward d at rate n. Topspin curves the
    /// ball toward -up (it dips), backspin toward +up (it floats). See docs/physics.md (frames and spin conventions).
    /// </remarks>
    public static class Spin
    {
        /// <summary>Converts revolutions per minute to rad/s.</summary>
        /// <param name="rpm">Spin rate, rev/min.</param>
        public static double FromRpm(double rpm) => rpm * (2.0 * Math.PI / 60.0);

        /// <summary>Converts revolutions per second to rad/s.</summary>
        /// <param name="revolutionsPerSecond">Spin rate, rev/s.</param>
        public static double FromRevolutionsPerSecond(double revolutionsPerSecond) => revolutionsPerSecond * (2.0 * Math.PI);

        /// <summary>Converts rad/s to revolutions per minute.</summary>
        /// <param name="radiansPerSecond">Spin rate, rad/s.</param>
        public static double ToRpm(double radiansPerSecond) => radiansPerSecond * (60.0 / (2.0 * Math.PI));

        /// <summary>
        /// The angular velocity of rate <paramref name="rate"/> whose Magnus force curves a ball moving along
        /// <paramref name="velocity"/> toward <paramref name="direction"/>: w = rate normalize(v x d).
        /// Only the part of d across v matters.
        /// </summary>
        /// <param name="velocity">The ball's (air-relative) velocity; finite, non-zero.</param>
        /// <param name="direction">Where the ball should curve; finite, not parallel to the velocity.</param>
        /// <param name="rate">Spin rate, rad/s; finite and &gt;= 0 (see <see cref="FromRpm"/>).</param>
        /// <exception cref="ArgumentException">
        /// A vector is zero or not finite, the two are parallel (no curve direction is defined), or the rate is out of range.
        /// </exception>
        public static Vector3d Toward(Vector3d velocity, Vector3d direction, double rate) =>
            Curve(velocity, direction, rate, direction, nameof(direction));

        // Toward, with the errors naming the caller's parameter: Topspin and Backspin pass their up (and -up or up
        // as the direction), so a vertical flight or a bad up is reported as "up", which is what the caller gave.
        private static Vector3d Curve(Vector3d velocity, Vector3d direction, double rate, Vector3d given, string givenName)
        {
            Require.NonZero(velocity, nameof(velocity));
            Require.NonZero(given, givenName);
            Require.NonNegative(rate, nameof(rate));
            Vector3d axis = Vector3d.Cross(velocity.NormalizedOrZero(), direction.NormalizedOrZero());
            double sine = axis.Length;
            if (!(sine > 1e-12))
            {
                throw new ArgumentException(
                    $"{givenName} must not be parallel to velocity (no curve direction across the flight is defined); got velocity {velocity}, {givenName} {given}.",
                    givenName);
            }

            return Overflow.Multiply(axis, rate / sine);
        }

        /// <summary>Topspin: spin that curves the ball down (toward -<paramref name="up"/>), so it dips.</summary>
        /// <param name="velocity">The ball's velocity; finite, not vertical.</param>
        /// <param name="up">The frame's up direction (for example -gravity); finite, non-zero.</param>
        /// <param name="rate">Spin rate, rad/s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">
        /// As for <see cref="Toward"/>, naming <paramref name="up"/> where it names the direction: up is zero or not
        /// finite, or parallel to the velocity (a vertical flight has no topspin axis).
        /// </exception>
        public static Vector3d Topspin(Vector3d velocity, Vector3d up, double rate) => Curve(velocity, -up, rate, up, nameof(up));

        /// <summary>Backspin: spin that curves the ball up (toward <paramref name="up"/>), so it floats.</summary>
        /// <param name="velocity">The ball's velocity; finite, not vertical.</param>
        /// <param name="up">The frame's up direction (for example -gravity); finite, non-zero.</param>
        /// <param name="rate">Spin rate, rad/s; finite and &gt;= 0.</param>
        /// <exception cref="ArgumentException">
        /// As for <see cref="Toward"/>, naming <paramref name="up"/> where it names the direction: up is zero or not
        /// finite, or parallel to the velocity (a vertical flight has no backspin axis).
        /// </exception>
        public static Vector3d Backspin(Vector3d velocity, Vector3d up, double rate) => Curve(velocity, up, rate, up, nameof(up));
    }
}
