using System;
using System.Runtime.CompilerServices;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    /// <summary>
    /// One step attempted by <see cref="DormandPrince54.TryStep"/>: its end state and end derivative, its error
    /// estimate, the step to try next, and its dense output, a fourth-order continuous extension that gives the
    /// state anywhere inside the step without another derivative evaluation.
    /// </summary>
    /// <remarks>
    /// The dense output is DOPRI5's (Shampine 1986; Hairer, Norsett &amp; Wanner 1993, II.6): with
    /// theta = (t - t0)/h, y(theta) = y0 + theta (dy + (1 - theta) (h k1 - dy + theta (r4 + (1 - theta) r5))),
    /// where dy = y1 - y0, r4 = dy - h k7 - (h k1 - dy) and r5 = h (d1 k1 + d3 k3 + d4 k4 + d5 k5 + d6 k6 + d7 k7).
    /// It matches y0 and y1 and the slopes k1 and k7 at both ends. A plain value (about 0.9 kB), filled in place by
    /// <see cref="DormandPrince54.TryStepInPlace"/>
    /// (the stages straight from the model's kernel, no copies): pass it by reference. Every member is readonly.
    /// </remarks>
    internal struct DormandPrince54Step : IDenseOutput
    {
        // The dense output's rows, each with a position, a velocity and a spin part.
        private StageRates _slopeDefect; // h k1 - dy
        private StageRates _r4;
        private StageRates _r5;

        /// <summary>
        /// Sets the step's outcome and builds its dense output from <see cref="Start"/>, <see cref="StartDerivative"/> and
        /// <see cref="Stages"/>, which the caller has written.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal void Complete(double step, double errorNorm, double nextStep, bool accepted)
        {
            Step = step;
            ErrorNorm = errorNorm;
            NextStep = nextStep;
            Accepted = accepted;
            DenseRows(step);
        }

        // The dense output's rows h k1 - dy, dy - h k7 - (h k1 - dy) and the fifth-order row.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private void DenseRows(double step)
        {
            ref readonly FlightState start = ref Start;
            ref readonly FlightState end = ref Stages.End;
            ref readonly StateDerivative k1 = ref StartDerivative;
            ref readonly StateDerivative k7 = ref Stages.K7;
            Vector3d dp = end.Position - start.Position;
            Vector3d dv = end.Velocity - start.Velocity;
            Vector3d dw = end.AngularVelocity - start.AngularVelocity;
            _slopeDefect.Set(k1.Velocity * step - dp, k1.Acceleration * step - dv, k1.AngularAcceleration * step - dw);
            _r4.Set(
                dp - k7.Velocity * step - _slopeDefect.Velocity,
                dv - k7.Acceleration * step - _slopeDefect.Acceleration,
                dw - k7.AngularAcceleration * step - _slopeDefect.AngularAcceleration);
            _r5.Set(
                Dense(k1.Velocity, Stages.K3.Velocity, Stages.K4.Velocity, Stages.K5.Velocity, Stages.K6.Velocity, k7.Velocity, step),
                Dense(k1.Acceleration, Stages.K3.Acceleration, Stages.K4.Acceleration, Stages.K5.Acceleration, Stages.K6.Acceleration, k7.Acceleration, step),
                Dense(k1.AngularAcceleration, Stages.K3.AngularAcceleration, Stages.K4.AngularAcceleration, Stages.K5.AngularAcceleration,
                    Stages.K6.AngularAcceleration, k7.AngularAcceleration, step));
        }

        /// <summary>
        /// Test hook: <see cref="InterpolateFraction"/> at <paramref name="theta"/> in [0, 1] is the Vector3d expression
        /// y0 + ((y1 - y0) + (D + (r4 + r5 (1 - theta)) theta) (1 - theta)) theta that Blend writes out component by
        /// component, the same bits.
        /// </summary>
        internal readonly bool InterpolationAlikeInBothForms(double theta)
        {
            double rest = 1 - theta;
            FlightState scalar = InterpolateFraction(theta);
            return Same(scalar.Position, VectorForm(Start.Position, Stages.End.Position, _slopeDefect.Velocity, _r4.Velocity, _r5.Velocity)) &&
                Same(scalar.Velocity, VectorForm(Start.Velocity, Stages.End.Velocity, _slopeDefect.Acceleration, _r4.Acceleration, _r5.Acceleration)) &&
                Same(scalar.AngularVelocity, VectorForm(
                    Start.AngularVelocity, Stages.End.AngularVelocity, _slopeDefect.AngularAcceleration, _r4.AngularAcceleration, _r5.AngularAcceleration));

            Vector3d VectorForm(in Vector3d y0, in Vector3d y1, in Vector3d defect, in Vector3d r4, in Vector3d r5) =>
                y0 + ((y1 - y0) + (defect + (r4 + r5 * rest) * theta) * rest) * theta;
        }

        private static bool Same(in Vector3d a, in Vector3d b) =>
            BitConverter.DoubleToInt64Bits(a.X) == BitConverter.DoubleToInt64Bits(b.X) &&
            BitConverter.DoubleToInt64Bits(a.Y) == BitConverter.DoubleToInt64Bits(b.Y) &&
            BitConverter.DoubleToInt64Bits(a.Z) == BitConverter.DoubleToInt64Bits(b.Z);

        /// <summary>True when the estimated error was within the tolerances and the step was taken.</summary>
        public bool Accepted;

        /// <summary>The state the step started from.</summary>
        public FlightState Start;

        /// <summary>The fifth-order end state and k2..k7 (k7 = f(End)), written by the model's kernel.</summary>
        public DormandPrince54Stages Stages;

        /// <summary>The fifth-order end state (meaningful when <see cref="Accepted"/>).</summary>
        public readonly FlightState End => Stages.End;

        /// <summary>The derivative at the start (k1).</summary>
        public StateDerivative StartDerivative;

        /// <summary>The derivative at the end, k7 = f(End): the next step's k1 (FSAL).</summary>
        public readonly StateDerivative EndDerivative => Stages.K7;

        /// <summary>The step attempted, s.</summary>
        public double Step;

        /// <summary>The scaled RMS error estimate; at most 1 when accepted.</summary>
        public double ErrorNorm;

        /// <summary>The step the controller suggests next, s (smaller than <see cref="Step"/> after a rejection).</summary>
        public double NextStep;

        /// <summary>
        /// The state at <paramref name="time"/> from the fourth-order dense output (no derivative evaluation).
        /// Times outside the step are clamped to it.
        /// </summary>
        /// <param name="time">The time, s; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">time is not finite.</exception>
        public readonly FlightState Interpolate(double time)
        {
            Require.Finite(time, nameof(time));
            double theta = Step > 0 ? (time - Start.Time) / Step : 1;
            theta = theta < 0 ? 0 : theta > 1 ? 1 : theta;
            return InterpolateFraction(theta);
        }

        /// <summary>The state at fraction <paramref name="theta"/> of the step (0 = start, 1 = end), clamped to [0, 1].</summary>
        /// <param name="theta">The fraction of the step; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">theta is not finite.</exception>
        public readonly FlightState InterpolateFraction(double theta)
        {
            Require.Finite(theta, nameof(theta));
            theta = theta < 0 ? 0 : theta > 1 ? 1 : theta;
            double rest = 1 - theta;
            FlightState y0 = Start;
            FlightState y1 = Stages.End;
            return new FlightState(
                Blend(y0.Position, y1.Position, _slopeDefect.Velocity, _r4.Velocity, _r5.Velocity, theta, rest),
                Blend(y0.Velocity, y1.Velocity, _slopeDefect.Acceleration, _r4.Acceleration, _r5.Acceleration, theta, rest),
                Blend(y0.AngularVelocity, y1.AngularVelocity, _slopeDefect.AngularAcceleration, _r4.AngularAcceleration, _r5.AngularAcceleration, theta, rest),
                theta == 1 ? y1.Time : y0.Time + theta * Step);
        }

        /// <inheritdoc />
        public readonly double StartTime => Start.Time;

        /// <inheritdoc />
        public readonly double EndTime => Stages.End.Time;

        /// <inheritdoc />
        public readonly FlightState StateAt(double time) => Interpolate(time);

        /// <inheritdoc />
        public readonly bool TryFindCrossing(in Plane plane, CrossingDirection direction, bool startsFlight, out double time)
        {
            double sign = direction == CrossingDirection.AgainstNormal ? 1.0 : -1.0;
            var condition = new PlaneDistance(plane, sign);
            double slope0 = sign * plane.NormalSpeed(StartDerivative.Velocity);
            return FirstFall(condition, startsFlight, slope0, out time);
        }

        /// <inheritdoc />
        public readonly bool TryFindApex(in Vector3d up, out double time) => FirstFall(new UpSpeed(up), false, 0, out time);

        /// <summary>
        /// True when the step provably holds no crossing of <paramref name="plane"/> in <paramref name="direction"/>:
        /// <see cref="TryFindCrossing"/> would find none (the ball stays on the side it starts on, with room for rounding).
        /// False means only that it may hold one.
        /// </summary>
        internal readonly bool StaysClearOf(in Plane plane, CrossingDirection direction)
        {
            var condition = new PlaneDistance(plane, direction == CrossingDirection.AgainstNormal ? 1.0 : -1.0);
            return StaysClear(condition, condition.QuickValue(Start), condition.QuickValue(Stages.End));
        }

        /// <summary>True when the step provably holds no apex along <paramref name="up"/> (<see cref="TryFindApex"/> would find none).</summary>
        internal readonly bool StaysClearOfApex(in Vector3d up)
        {
            var condition = new UpSpeed(up);
            return StaysClear(condition, condition.QuickValue(Start), condition.QuickValue(Stages.End));
        }

        /// <summary>Samples per step when looking for a sign change of a condition on the quartic interpolant.</summary>
        private const int Samples = 8;

        /// <summary>
        /// The rounding margin of the no-event bound (StaysClearOf), relative to the sum of the magnitudes a sample is
        /// computed from: a sample's rounding error is a few dozen ulp of that sum at most (about 4e-15 of it), so this is
        /// more than 200 times that.
        /// </summary>
        internal const double BoundMargin = 1e-12;

        // The first fall of g from > 0 to <= 0 on the interpolant: sampled at 9 points (the quartic in theta has at most 3
        // turning points, so 8 intervals catch every sign change a flight produces within one accepted step), then
        // refined by the Illinois method to HermiteSegment.TimeTolerance. Bounded: at most 200 refinement passes. A step
        // the condition provably stays above zero on, or below it (StaysClear), is not sampled: every sample would be on
        // that side, so the answer (none) is the same.
        private readonly bool FirstFall<TCondition>(in TCondition condition, bool fromZero, double slope0, out double time)
            where TCondition : struct, IStepCondition
        {
            time = 0;
            double g0 = condition.Value(Start);
            if (!double.IsFinite(g0))
            {
                return false;
            }

            if (fromZero && g0 == 0 && slope0 < 0)
            {
                time = Start.Time;
                return true;
            }

            double g1 = condition.Value(Stages.End);
            if (StaysClear(condition, g0, g1))
            {
                return false;
            }

            double lo = 0, glo = g0;
            for (int i = 1; i <= Samples; i++)
            {
                double theta = (double)i / Samples;
                double g = i == Samples ? g1 : condition.At(this, theta);
                if (glo > 0 && g <= 0)
                {
                    time = Refine(condition, lo, glo, theta, g);
                    return true;
                }

                lo = theta;
                glo = g;
            }

            return false;
        }

        // True when the condition provably cannot fall from > 0 to <= 0 at the samples: it stays above zero all through
        // the step, or below it, with room for the rounding of each sample. With theta in [0, 1] the interpolant is
        // y0 + theta dy + theta (1 - theta) D + theta^2 (1 - theta) r4 + theta^2 (1 - theta)^2 r5 (the form Blend
        // evaluates), and theta (1 - theta) <= 1/4, theta^2 (1 - theta) <= 4/27, theta^2 (1 - theta)^2 <= 1/16; the
        // condition is affine in the state, so at every theta it lies within min(g0, g1) + (1/4) min(0, d) + (4/27) min(0, r4)
        // + (1/16) min(0, r5) and the same with max, d, r4, r5 being its linear part applied to D, r4, r5. False (sample)
        // when anything is not finite.
        private readonly bool StaysClear<TCondition>(in TCondition condition, double g0, double g1)
            where TCondition : struct, IStepCondition
        {
            double d = condition.Linear(_slopeDefect), r4 = condition.Linear(_r4), r5 = condition.Linear(_r5);
            double margin = BoundMargin * condition.Magnitude(this);
            // Every number finite (x - x is 0 for a finite x and NaN otherwise, as in StepArguments.Check). Not a test of their
            // sum: that overflows for some finite numbers (a plane 9e307 m away), where the bound below still decides.
            if ((g0 - g0) + (g1 - g1) + (d - d) + (r4 - r4) + (r5 - r5) + (margin - margin) != 0)
            {
                return false;
            }

            // Finite from here, so plain comparisons (Math.Min/Max's NaN and signed-zero rules cannot change a decision).
            double lower = (g0 < g1 ? g0 : g1) + 0.25 * (d < 0 ? d : 0) + (4.0 / 27) * (r4 < 0 ? r4 : 0) + 0.0625 * (r5 < 0 ? r5 : 0);
            if (lower > margin)
            {
                return true;
            }

            double upper = (g0 > g1 ? g0 : g1) + 0.25 * (d > 0 ? d : 0) + (4.0 / 27) * (r4 > 0 ? r4 : 0) + 0.0625 * (r5 > 0 ? r5 : 0);
            return upper < -margin;
        }

        private readonly double Refine<TCondition>(in TCondition condition, double lo, double glo, double hi, double ghi)
            where TCondition : struct, IStepCondition
        {
            double tolerance = Step > 0 ? HermiteSegment.TimeTolerance / Step : 1;
            int side = 0;
            for (int i = 0; i < 200 && hi - lo > tolerance && ghi != 0; i++)
            {
                double theta = (glo * hi - ghi * lo) / (glo - ghi);
                if (!(theta > lo && theta < hi))
                {
                    theta = 0.5 * (lo + hi);
                }

                double g = condition.At(this, theta);
                if (g > 0)
                {
                    lo = theta;
                    glo = g;
                    if (side == -1)
                    {
                        ghi *= 0.5;
                    }

                    side = -1;
                }
                else
                {
                    hi = theta;
                    ghi = g;
                    if (side == 1)
                    {
                        glo *= 0.5;
                    }

                    side = 1;
                }
            }

            return hi >= 1 ? Stages.End.Time : Start.Time + hi * Step;
        }

        // The position and the velocity at fraction theta in [0, 1]: InterpolateFraction's, bit for bit, without the rest.
        private readonly Vector3d PositionAt(double theta) =>
            Blend(Start.Position, Stages.End.Position, _slopeDefect.Velocity, _r4.Velocity, _r5.Velocity, theta, 1 - theta);

        private readonly Vector3d VelocityAt(double theta) =>
            Blend(Start.Velocity, Stages.End.Velocity, _slopeDefect.Acceleration, _r4.Acceleration, _r5.Acceleration, theta, 1 - theta);

        // A condition on the state, affine in it: Value(state) = Linear(the part of the state it reads) + a constant.
        private interface IStepCondition
        {
            // The condition at a state.
            double Value(in FlightState state);

            // The same for the quick test (StaysClear), which treats a non-finite value as "not sure": a plane's distance
            // without Plane.SignedDistance's overflow check, which the search (Value, At) then applies.
            double QuickValue(in FlightState state);

            // The condition at fraction theta of the step: Value(InterpolateFraction(theta)) bit for bit, computing only the
            // part of the state it reads.
            double At(in DormandPrince54Step step, double theta);

            // The linear part applied to a dense-output coefficient (its position rows for a plane, velocity rows for up).
            double Linear(in StageRates coefficient);

            // The sum of the magnitudes a sample is computed from (for the rounding margin).
            double Magnitude(in DormandPrince54Step step);
        }

        private readonly struct PlaneDistance : IStepCondition
        {
            private readonly Plane _plane;
            private readonly double _sign;

            public PlaneDistance(in Plane plane, double sign)
            {
                _plane = plane;
                _sign = sign;
            }

            public double Value(in FlightState state) => _sign * _plane.SignedDistance(state.Position);

            public double QuickValue(in FlightState state) => _sign * _plane.UncheckedSignedDistance(state.Position);

            public double At(in DormandPrince54Step step, double theta) => _sign * _plane.SignedDistance(step.PositionAt(theta));

            public double Linear(in StageRates coefficient) => _sign * Vector3d.Dot(coefficient.Velocity, _plane.Normal);

            public double Magnitude(in DormandPrince54Step step) =>
                Weighted(step.Start.Position) + Weighted(step.Stages.End.Position) + Weighted(step._slopeDefect.Velocity) + Weighted(step._r4.Velocity) +
                Weighted(step._r5.Velocity) + Weighted(_plane.Point);

            private double Weighted(in Vector3d x) => AbsoluteDot(x, _plane.Normal);
        }

        private readonly struct UpSpeed : IStepCondition
        {
            private readonly Vector3d _up;

            public UpSpeed(in Vector3d up) => _up = up;

            public double Value(in FlightState state) => Vector3d.Dot(state.Velocity, _up);

            public double QuickValue(in FlightState state) => Value(state);

            public double At(in DormandPrince54Step step, double theta) => Vector3d.Dot(step.VelocityAt(theta), _up);

            public double Linear(in StageRates coefficient) => Vector3d.Dot(coefficient.Acceleration, _up);

            public double Magnitude(in DormandPrince54Step step) =>
                AbsoluteDot(step.Start.Velocity, _up) + AbsoluteDot(step.Stages.End.Velocity, _up) + AbsoluteDot(step._slopeDefect.Acceleration, _up) +
                AbsoluteDot(step._r4.Acceleration, _up) + AbsoluteDot(step._r5.Acceleration, _up);
        }

        // sum |x_i| |n_i|: what the rounding of x . n (or (x - point) . n) is relative to.
        private static double AbsoluteDot(in Vector3d x, in Vector3d n)
        {
            double ax = Math.Abs(x.X), ay = Math.Abs(x.Y), az = Math.Abs(x.Z);
            return ax * Math.Abs(n.X) + ay * Math.Abs(n.Y) + az * Math.Abs(n.Z);
        }

        // y0 + ((y1 - y0) + (defect + (r4 + r5 rest) theta) rest) theta, component by component: the same operations in the
        // same order as the Vector3d expression, without its eight vector temporaries (which Mono zeroes and stores).
        private static Vector3d Blend(in Vector3d y0, in Vector3d y1, in Vector3d defect, in Vector3d r4, in Vector3d r5, double theta, double rest) =>
            new Vector3d(
                y0.X + ((y1.X - y0.X) + (defect.X + (r4.X + r5.X * rest) * theta) * rest) * theta,
                y0.Y + ((y1.Y - y0.Y) + (defect.Y + (r4.Y + r5.Y * rest) * theta) * rest) * theta,
                y0.Z + ((y1.Z - y0.Z) + (defect.Z + (r4.Z + r5.Z * rest) * theta) * rest) * theta);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3d Dense(in Vector3d k1, in Vector3d k3, in Vector3d k4, in Vector3d k5, in Vector3d k6, in Vector3d k7, double h) =>
            (k1 * D1 + k3 * D3 + k4 * D4 + k5 * D5 + k6 * D6 + k7 * D7) * h;

        private const double D1 = -12715105075.0 / 11282082432, D3 = 87487479700.0 / 32700410799, D4 = -10690763975.0 / 1880347072;
        private const double D5 = 701980252875.0 / 199316789632, D6 = -1453857185.0 / 822651844, D7 = 69997945.0 / 29380423;
    }
}
