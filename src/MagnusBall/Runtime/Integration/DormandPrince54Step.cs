using System;

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
    /// It matches y0 and y1 and the slopes k1 and k7 at both ends. A plain value (about 0.5 kB): pass it by
    /// reference (<c>in</c>) where it matters.
    /// </remarks>
    internal readonly struct DormandPrince54Step : IDenseOutput
    {
        private readonly StateDerivative _slopeDefect; // h k1 - dy
        private readonly StateDerivative _r4;
        private readonly StateDerivative _r5;

        internal DormandPrince54Step(
            in FlightState start,
            in FlightState end,
            in StateDerivative k1,
            in StateDerivative k3,
            in StateDerivative k4,
            in StateDerivative k5,
            in StateDerivative k6,
            in StateDerivative k7,
            double step,
            double errorNorm,
            double nextStep,
            bool accepted)
        {
            Start = start;
            End = end;
            StartDerivative = k1;
            EndDerivative = k7;
            Step = step;
            ErrorNorm = errorNorm;
            NextStep = nextStep;
            Accepted = accepted;

            Vector3d dp = end.Position - start.Position;
            Vector3d dv = end.Velocity - start.Velocity;
            Vector3d dw = end.AngularVelocity - start.AngularVelocity;
            _slopeDefect = new StateDerivative(k1.Velocity * step - dp, k1.Acceleration * step - dv, k1.AngularAcceleration * step - dw);
            _r4 = new StateDerivative(
                dp - k7.Velocity * step - _slopeDefect.Velocity,
                dv - k7.Acceleration * step - _slopeDefect.Acceleration,
                dw - k7.AngularAcceleration * step - _slopeDefect.AngularAcceleration);
            _r5 = new StateDerivative(
                Dense(k1.Velocity, k3.Velocity, k4.Velocity, k5.Velocity, k6.Velocity, k7.Velocity, step),
                Dense(k1.Acceleration, k3.Acceleration, k4.Acceleration, k5.Acceleration, k6.Acceleration, k7.Acceleration, step),
                Dense(k1.AngularAcceleration, k3.AngularAcceleration, k4.AngularAcceleration, k5.AngularAcceleration, k6.AngularAcceleration,
                    k7.AngularAcceleration, step));
        }

        /// <summary>True when the estimated error was within the tolerances and the step was taken.</summary>
        public bool Accepted { get; }

        /// <summary>The state the step started from.</summary>
        public FlightState Start { get; }

        /// <summary>The fifth-order end state (meaningful when <see cref="Accepted"/>).</summary>
        public FlightState End { get; }

        /// <summary>The derivative at the start (k1).</summary>
        public StateDerivative StartDerivative { get; }

        /// <summary>The derivative at the end, k7 = f(End): the next step's k1 (FSAL).</summary>
        public StateDerivative EndDerivative { get; }

        /// <summary>The step attempted, s.</summary>
        public double Step { get; }

        /// <summary>The scaled RMS error estimate; at most 1 when accepted.</summary>
        public double ErrorNorm { get; }

        /// <summary>The step the controller suggests next, s (smaller than <see cref="Step"/> after a rejection).</summary>
        public double NextStep { get; }

        /// <summary>
        /// The state at <paramref name="time"/> from the fourth-order dense output (no derivative evaluation).
        /// Times outside the step are clamped to it.
        /// </summary>
        /// <param name="time">The time, s; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">time is not finite.</exception>
        public FlightState Interpolate(double time)
        {
            Require.Finite(time, nameof(time));
            double theta = Step > 0 ? (time - Start.Time) / Step : 1;
            theta = theta < 0 ? 0 : theta > 1 ? 1 : theta;
            return InterpolateFraction(theta);
        }

        /// <summary>The state at fraction <paramref name="theta"/> of the step (0 = start, 1 = end), clamped to [0, 1].</summary>
        /// <param name="theta">The fraction of the step; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">theta is not finite.</exception>
        public FlightState InterpolateFraction(double theta)
        {
            Require.Finite(theta, nameof(theta));
            theta = theta < 0 ? 0 : theta > 1 ? 1 : theta;
            double rest = 1 - theta;
            FlightState y0 = Start;
            FlightState y1 = End;
            return new FlightState(
                Blend(y0.Position, y1.Position, _slopeDefect.Velocity, _r4.Velocity, _r5.Velocity, theta, rest),
                Blend(y0.Velocity, y1.Velocity, _slopeDefect.Acceleration, _r4.Acceleration, _r5.Acceleration, theta, rest),
                Blend(y0.AngularVelocity, y1.AngularVelocity, _slopeDefect.AngularAcceleration, _r4.AngularAcceleration, _r5.AngularAcceleration, theta, rest),
                theta == 1 ? y1.Time : y0.Time + theta * Step);
        }

        /// <inheritdoc />
        public double StartTime => Start.Time;

        /// <inheritdoc />
        public double EndTime => End.Time;

        /// <inheritdoc />
        public FlightState StateAt(double time) => Interpolate(time);

        /// <inheritdoc />
        public bool TryFindCrossing(in Plane plane, CrossingDirection direction, bool startsFlight, out double time)
        {
            double sign = direction == CrossingDirection.AgainstNormal ? 1.0 : -1.0;
            var condition = new PlaneDistance(plane, sign);
            double slope0 = sign * plane.NormalSpeed(StartDerivative.Velocity);
            return FirstFall(condition, startsFlight, slope0, out time);
        }

        /// <inheritdoc />
        public bool TryFindApex(in Vector3d up, out double time) => FirstFall(new UpSpeed(up), false, 0, out time);

        /// <summary>Samples per step when looking for a sign change of a condition on the quartic interpolant.</summary>
        private const int Samples = 8;

        // The first fall of g from > 0 to <= 0 on the interpolant: sampled at 9 points (the quartic in theta has at most 3
        // turning points, so 8 intervals catch every sign change a flight produces within one accepted step), then
        // refined by the Illinois method to HermiteSegment.TimeTolerance. Bounded: at most 200 refinement passes.
        private bool FirstFall<TCondition>(in TCondition condition, bool fromZero, double slope0, out double time)
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

            double lo = 0, glo = g0;
            for (int i = 1; i <= Samples; i++)
            {
                double theta = (double)i / Samples;
                double g = condition.Value(i == Samples ? End : InterpolateFraction(theta));
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

        private double Refine<TCondition>(in TCondition condition, double lo, double glo, double hi, double ghi)
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

                double g = condition.Value(InterpolateFraction(theta));
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

            return hi >= 1 ? End.Time : Start.Time + hi * Step;
        }

        private interface IStepCondition
        {
            double Value(in FlightState state);
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
        }

        private readonly struct UpSpeed : IStepCondition
        {
            private readonly Vector3d _up;

            public UpSpeed(in Vector3d up) => _up = up;

            public double Value(in FlightState state) => Vector3d.Dot(state.Velocity, _up);
        }

        private static Vector3d Blend(in Vector3d y0, in Vector3d y1, in Vector3d defect, in Vector3d r4, in Vector3d r5, double theta, double rest) =>
            y0 + ((y1 - y0) + (defect + (r4 + r5 * rest) * theta) * rest) * theta;

        private static Vector3d Dense(in Vector3d k1, in Vector3d k3, in Vector3d k4, in Vector3d k5, in Vector3d k6, in Vector3d k7, double h) =>
            (k1 * D1 + k3 * D3 + k4 * D4 + k5 * D5 + k6 * D6 + k7 * D7) * h;

        private const double D1 = -12715105075.0 / 11282082432, D3 = 87487479700.0 / 32700410799, D4 = -10690763975.0 / 1880347072;
        private const double D5 = 701980252875.0 / 199316789632, D6 = -1453857185.0 / 822651844, D7 = 69997945.0 / 29380423;
    }
}
