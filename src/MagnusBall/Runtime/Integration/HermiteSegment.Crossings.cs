// HermiteSegment, part: the event searches on the cubic (TryFindCrossing, TryFindApex), the quick tests that rule an
// event out without a search (SurelyNoCrossing, SurelyNoApex, CannotFall), and the first fall's root and its refinement
// (FirstFall, Refine). The segment itself is in HermiteSegment.cs.
using System;
using System.Runtime.CompilerServices;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    internal readonly partial struct HermiteSegment
    {
        /// <summary>
        /// Finds the first time inside a step that continues a flight at which the ball crosses
        /// <paramref name="plane"/> in the given direction: the same as
        /// <see cref="TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/> with startsFlight false.
        /// A crossing against the normal goes from strictly positive to zero or below (a ball that starts the
        /// step exactly on the plane crossed it, if at all, at the end of the previous step); along the normal,
        /// from strictly negative to zero or above.
        /// </summary>
        /// <param name="plane">The plane.</param>
        /// <param name="direction">Which way the crossing must go.</param>
        /// <param name="time">The crossing time to <see cref="TimeTolerance"/>, s; 0 when none is found.</param>
        /// <returns>True when the interpolated path crosses the plane that way inside (StartTime, EndTime].</returns>
        /// <exception cref="System.ArgumentOutOfRangeException">The direction is not a defined <see cref="CrossingDirection"/>.</exception>
        public bool TryFindCrossing(in Plane plane, CrossingDirection direction, out double time) =>
            TryFindCrossing(plane, direction, false, out time);

        /// <summary>
        /// Finds the first time inside the step at which the ball crosses <paramref name="plane"/> in the given
        /// direction. A crossing against the normal goes from strictly positive to zero or below; along the
        /// normal, from strictly negative to zero or above. When <paramref name="startsFlight"/> is true, a ball
        /// that starts the step exactly on the plane (signed distance 0) and heads through it at once (the
        /// cubic's slope points through the plane, or the slope is 0 and its curvature does) crosses it at
        /// <see cref="StartTime"/>: a ball launched from the ground into the ground lands at once.
        /// </summary>
        /// <remarks>
        /// Pass startsFlight true only for the first step after a flight was started or its state replaced
        /// (the flight core's Reset or SetState). A later step starts where
        /// the previous one ended: if that end lay exactly on the plane, the previous step already reported the
        /// crossing there (or the ball reached the plane from the far side and did not cross it), so counting the
        /// start again would report one crossing twice. A ball leaving the plane (after a bounce) does not head
        /// through it and is never counted.
        /// </remarks>
        /// <param name="plane">The plane.</param>
        /// <param name="direction">Which way the crossing must go.</param>
        /// <param name="startsFlight">True for the first step of a flight: a start exactly on the plane heading through it counts.</param>
        /// <param name="time">The crossing time to <see cref="TimeTolerance"/>, s; 0 when none is found.</param>
        /// <returns>
        /// True when the interpolated path crosses the plane that way inside (StartTime, EndTime], or at
        /// StartTime as described for <paramref name="startsFlight"/>.
        /// </returns>
        /// <exception cref="System.ArgumentOutOfRangeException">The direction is not a defined <see cref="CrossingDirection"/>.</exception>
        public bool TryFindCrossing(in Plane plane, CrossingDirection direction, bool startsFlight, out double time)
        {
            if (direction != CrossingDirection.AlongNormal && direction != CrossingDirection.AgainstNormal)
            {
                throw new System.ArgumentOutOfRangeException(
                    nameof(direction), direction, $"direction must be CrossingDirection.AlongNormal or AgainstNormal; got {(int)direction}.");
            }

            CrossingCubic(plane, direction, Start, StartDerivative, End, EndDerivative, out double f0, out double m0, out double f1, out double m1);
            if (!double.IsFinite(f0) || !double.IsFinite(f1))
            {
                // The plain distance overflowed (a plane's point near 1e308 away): Plane.SignedDistance's safe form.
                double sign = direction == CrossingDirection.AgainstNormal ? 1.0 : -1.0;
                f0 = sign * plane.SignedDistance(Start.Position);
                f1 = sign * plane.SignedDistance(End.Position);
            }

            return FirstFall(f0, m0, f1, m1, startsFlight, out time);
        }

        // The scalar cubic TryFindCrossing searches (values and slopes times the step), from the segment's ends.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void CrossingCubic(
            in Plane plane, CrossingDirection direction, in FlightState start, in StateDerivative startDerivative, in FlightState end,
            in StateDerivative endDerivative, out double f0, out double m0, out double f1, out double m1)
        {
            double h = end.Time - start.Time;
            double sign = direction == CrossingDirection.AgainstNormal ? 1.0 : -1.0;
            // The plain distances (no overflow check on the common step): a non-finite one (a plane's point near 1e308 away)
            // makes the quick test answer "not sure", and the search forms it again with Plane.SignedDistance's safe path.
            f0 = sign * plane.UncheckedSignedDistance(start.Position);
            m0 = sign * plane.NormalSpeed(startDerivative.Velocity) * h;
            f1 = sign * plane.UncheckedSignedDistance(end.Position);
            m1 = sign * plane.NormalSpeed(endDerivative.Velocity) * h;
        }

        // The scalar cubic TryFindApex searches.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void ApexCubic(
            in Vector3d up, in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative,
            out double f0, out double m0, out double f1, out double m1)
        {
            double h = end.Time - start.Time;
            f0 = Vector3d.Dot(start.Velocity, up);
            m0 = Vector3d.Dot(startDerivative.Acceleration, up) * h;
            f1 = Vector3d.Dot(end.Velocity, up);
            m1 = Vector3d.Dot(endDerivative.Acceleration, up) * h;
        }

        /// <summary>
        /// True when the segment from these ends surely holds no crossing of <paramref name="plane"/> in the given direction:
        /// <see cref="TryFindCrossing(in Plane, CrossingDirection, bool, out double)"/> would return false (its own first
        /// test, on the same numbers wherever this can answer true: the plain distances here equal the checked ones the search
        /// forms whenever they are finite, and a number that is not finite makes this false), so the flight core can skip
        /// building the segment.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool SurelyNoCrossing(
            in Plane plane, CrossingDirection direction, in FlightState start, in StateDerivative startDerivative, in FlightState end,
            in StateDerivative endDerivative)
        {
            CrossingCubic(plane, direction, start, startDerivative, end, endDerivative, out double f0, out double m0, out double f1, out double m1);
            return CannotFall(f0, m0, f1, m1);
        }

        /// <summary>As <see cref="SurelyNoCrossing"/>, for <see cref="TryFindApex"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool SurelyNoApex(
            in Vector3d up, in FlightState start, in StateDerivative startDerivative, in FlightState end, in StateDerivative endDerivative)
        {
            ApexCubic(up, start, startDerivative, end, endDerivative, out double f0, out double m0, out double f1, out double m1);
            return CannotFall(f0, m0, f1, m1);
        }

        /// <summary>
        /// Finds the first time inside the step at which the velocity along <paramref name="up"/> changes from
        /// positive to zero or below: the top of the flight.
        /// </summary>
        /// <param name="up">The up direction (for example <see cref="FlightModel.Up"/>); need not be unit length.</param>
        /// <param name="time">The apex time to <see cref="TimeTolerance"/>, s; 0 when none is found.</param>
        /// <returns>True when the apex falls inside (StartTime, EndTime].</returns>
        public bool TryFindApex(in Vector3d up, out double time)
        {
            ApexCubic(up, Start, StartDerivative, End, EndDerivative, out double f0, out double m0, out double f1, out double m1);
            return FirstFall(f0, m0, f1, m1, false, out time);
        }

        /// <summary>
        /// True when the scalar Hermite cubic (values f0, f1, slopes times h m0, m1) surely has no fall from &gt; 0 to
        /// &lt;= 0 on [0, 1]: <see cref="FirstFall"/>'s quick exits, which decide most steps (no event).
        /// </summary>
        /// <remarks>
        /// On [0, 1] the Hermite basis functions h00 + h01 = 1 (both in [0, 1]), h10 in [0, 4/27] and h11 in [-4/27, 0]
        /// bound f(s) &gt;= min(f0, f1) - 4/27 (max(-m0, 0) + max(m1, 0)). When that is clearly positive there is no root; the
        /// margin (1e-9 of the data, far above the rounding of the polynomial form FirstFall evaluates) keeps the answer the
        /// full search would give. Nor can a cubic that stays clearly below 0 fall from above it (the apex test on the way
        /// down): by the same bounds f(s) &lt;= max(f0, f1) + 4/27 (max(m0, 0) + max(-m1, 0)). With the margin every value the
        /// full search evaluates is negative too, so it finds no start above 0. (f0 = 0 never passes: the bound is then &gt;= 0.)
        /// </remarks>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool CannotFall(double f0, double m0, double f1, double m1)
        {
            // A finite sum means four finite numbers (the common case, one test). Otherwise: not sure. Four finite numbers near
            // 1e308 (a plane that far away) must go on to the search, and so must a non-finite one, which from finite states
            // is an overflow of the quick test's plain distance that the search forms again without it (Plane.SignedDistance);
            // the search itself finds nothing on numbers that are still not finite.
            if (!double.IsFinite(f0 + m0 + f1 + m1))
            {
                return false;
            }

            // (Plain comparisons, not Math.Min/Max: the numbers are finite here, so their NaN and signed-zero rules, a dozen
            // instructions each, cannot change a decision.)
            double scale = 1e-9 * (Math.Abs(f0) + Math.Abs(f1) + Math.Abs(m0) + Math.Abs(m1));
            double low = (f0 < f1 ? f0 : f1) - (4.0 / 27.0) * ((m0 < 0 ? -m0 : 0) + (m1 > 0 ? m1 : 0));
            if (low > scale)
            {
                return true;
            }

            double high = (f0 > f1 ? f0 : f1) + (4.0 / 27.0) * ((m0 > 0 ? m0 : 0) + (m1 < 0 ? -m1 : 0));
            return high < -scale;
        }

        /// <summary>
        /// First s in (0, 1] where the scalar Hermite cubic with values f0, f1 and scaled slopes m0, m1 (slope
        /// times h) falls from &gt; 0 to &lt;= 0; converted to time. With <paramref name="fromZero"/>, also s = 0
        /// when f0 is 0 and the cubic falls below 0 at once (slope &lt; 0, or slope 0 and curvature &lt; 0, or
        /// both 0 and the cubic term &lt; 0).
        /// </summary>
        private bool FirstFall(double f0, double m0, double f1, double m1, bool fromZero, out double time)
        {
            time = 0;
            // Nothing to find on a cubic that is not finite (x - x is 0 for a finite x and NaN otherwise); tested only where the
            // sum is not finite, so the common step pays one test.
            if (!double.IsFinite(f0 + m0 + f1 + m1) && ((f0 - f0) + (m0 - m0)) + ((f1 - f1) + (m1 - m1)) != 0)
            {
                return false;
            }

            if (CannotFall(f0, m0, f1, m1))
            {
                return false;
            }

            // Finite but huge (a plane 1e150 m or more away): the coefficients and the discriminant below would overflow (the
            // discriminant squares them). Where the cubic falls does not depend on its scale, so the four numbers are scaled
            // by 2^-600, which is exact for numbers of 2^-422 (about 1e-127) or more; smaller ones round to a subnormal, and
            // those of 2^-475 (about 1e-143) or less would round to 0: they are kept at the smallest double of their sign, so the
            // tests below of f0 == 0, f0 > 0, f1 <= 0 and of the slope's sign see each number's own sign. Sums under 1e150 are
            // used as they are: ordinary steps bit for bit.
            if (!(Math.Abs(f0) + Math.Abs(m0) + Math.Abs(f1) + Math.Abs(m1) < 1e150))
            {
                f0 = ScaledDown(f0);
                m0 = ScaledDown(m0);
                f1 = ScaledDown(f1);
                m1 = ScaledDown(m1);
            }

            // f(s) = a s^3 + b s^2 + c s + d
            double a = 2 * f0 + m0 - 2 * f1 + m1;
            double b = -3 * f0 - 2 * m0 + 3 * f1 - m1;
            double c = m0;
            if (fromZero && f0 == 0 && (c < 0 || (c == 0 && (b < 0 || (b == 0 && a < 0)))))
            {
                time = Start.Time;
                return true;
            }

            // Turning points: 3a s^2 + 2b s + c = 0, kept when inside (0, 1), sorted.
            double r1 = double.NaN, r2 = double.NaN;
            double qa = 3 * a, qb = 2 * b;
            if (qa != 0)
            {
                double disc = qb * qb - 4 * qa * c;
                if (disc > 0)
                {
                    double q = -0.5 * (qb + (qb >= 0 ? Math.Sqrt(disc) : -Math.Sqrt(disc)));
                    r1 = q / qa;
                    r2 = q != 0 ? c / q : double.NaN;
                }
            }
            else if (qb != 0)
            {
                r1 = -c / qb;
            }

            if (r1 > r2)
            {
                double t = r1;
                r1 = r2;
                r2 = t;
            }

            double lo = 0, flo = f0;
            if (r1 > 0 && r1 < 1)
            {
                double fr = Evaluate(a, b, c, f0, r1);
                if (flo > 0 && fr <= 0)
                {
                    return Refine(a, b, c, f0, lo, r1, out time);
                }

                lo = r1;
                flo = fr;
            }

            if (r2 > 0 && r2 < 1)
            {
                double fr = Evaluate(a, b, c, f0, r2);
                if (flo > 0 && fr <= 0)
                {
                    return Refine(a, b, c, f0, lo, r2, out time);
                }

                lo = r2;
                flo = fr;
            }

            if (flo > 0 && f1 <= 0)
            {
                if (f1 == 0 && lo == 0)
                {
                    // Exactly on the plane at the end of the step; no refinement can do better.
                    time = End.Time;
                    return true;
                }

                return Refine(a, b, c, f0, lo, 1, out time);
            }

            return false;
        }

        // x times 2^-600, or the smallest double of x's sign where that product would round to 0 from a number that is not 0.
        private static double ScaledDown(double x)
        {
            const double Down = 2.409919865102884e-181; // 2^-600
            double y = x * Down;
            return y != 0 || x == 0 ? y : x > 0 ? double.Epsilon : -double.Epsilon;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Evaluate(double a, double b, double c, double d, double s) => ((a * s + b) * s + c) * s + d;

        /// <summary>Root of the monotone falling cubic on [lo, hi] (f(lo) &gt; 0 &gt;= f(hi)) by Newton-bisection.</summary>
        private bool Refine(double a, double b, double c, double d, double lo, double hi, out double time)
        {
            double h = Duration;
            double tolerance = TimeTolerance / h;
            double s = 0.5 * (lo + hi);
            double previousWidth = hi - lo;
            for (int i = 0; i < 200; i++)
            {
                double f = Evaluate(a, b, c, d, s);
                if (f > 0)
                {
                    lo = s;
                }
                else
                {
                    hi = s;
                }

                if (f == 0 || hi - lo <= tolerance)
                {
                    break;
                }

                double slope = (3 * a * s + 2 * b) * s + c;
                double newton = slope != 0 ? s - f / slope : double.NaN;
                double width = hi - lo;
                if (newton > lo && newton < hi && width < 0.75 * previousWidth)
                {
                    if (Math.Abs(newton - s) <= 0.25 * tolerance)
                    {
                        s = newton;
                        break;
                    }

                    s = newton;
                }
                else
                {
                    s = 0.5 * (lo + hi);
                }

                previousWidth = width;
            }

            if (s < 0)
            {
                s = 0;
            }
            else if (s > 1)
            {
                s = 1;
            }

            time = s >= 1 ? End.Time : Start.Time + s * h;
            return true;
        }
    }
}
