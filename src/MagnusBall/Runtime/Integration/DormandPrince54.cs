using System;
using System.Runtime.CompilerServices;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    /// <summary>
    /// The Dormand-Prince 5(4) embedded Runge-Kutta pair: a fifth-order solution, a fourth-order
    /// error estimate, first-same-as-last (FSAL) and a fourth-order continuous extension (dense output).
    /// </summary>
    /// <remarks>
    /// <para>Source: Dormand &amp; Prince (1980), "A family of embedded Runge-Kutta formulae", J. Comput.
    /// Appl. Math. 6:19 (the tableau); Hairer, Norsett &amp; Wanner (1993), Solving Ordinary Differential
    /// Equations I, 2nd ed., section II.4-II.6 (the error norm, the step-size controller, the initial-step
    /// heuristic and the dense output of DOPRI5, whose coefficients are Shampine's (1986)).</para>
    /// <para>Two ways to use it:</para>
    /// <list type="bullet">
    /// <item>As a fixed-step <see cref="IIntegrator"/>: <see cref="IIntegrator.Step"/> takes the fifth-order solution
    /// of one step and ignores the error estimate. Six evaluations per step (k2..k6 and the FSAL stage
    /// k7 = f(y1), returned as the end derivative: the caller's next k1, as for every integrator here).</item>
    /// <item>Adaptively: <see cref="TryStep"/> attempts one step and reports whether its estimated error is
    /// within the tolerances, the step to try next, the end derivative (k7, so a loop pays six evaluations per
    /// accepted step) and a <see cref="DormandPrince54Step"/> with the dense output;
    /// the flight core steps with it (FlightStepper.TryStepAdaptive), locating events on the method's own interpolant. Use it for reference solutions
    /// and offline work such as aim solving, where accuracy matters more than a fixed frame step.</item>
    /// </list>
    /// <para>The error of a step is the root mean square over the nine state components of
    /// err_i / (atol + rtol max(|y0_i|, |y1_i|)); a step is accepted when that norm is at most 1. The next
    /// step is h 0.9 norm^(-1/5), kept within [0.2 h, 5 h] (at most h after a rejection). All of it runs on
    /// the stack: nothing is allocated.</para>
    /// </remarks>
    public sealed class DormandPrince54 : IIntegrator
    {
        // Dormand & Prince (1980), the 5(4) tableau ("RK5(4)7M"); the flight kernel's stages use the same constants.
        private const double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9;
        internal const double A21 = 1.0 / 5;
        internal const double A31 = 3.0 / 40, A32 = 9.0 / 40;
        internal const double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
        internal const double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729;
        internal const double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176, A65 = -5103.0 / 18656;
        internal const double B1 = 35.0 / 384, B3 = 500.0 / 1113, B4 = 125.0 / 192, B5 = -2187.0 / 6784, B6 = 11.0 / 84;

        // The error weights b - b_hat (fifth minus fourth order), the last on k7 = f(y1).
        private const double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200, E6 = 22.0 / 525, E7 = -1.0 / 40;

        private const double Safety = 0.9;
        private const double MinimumFactor = 0.2;
        private const double MaximumFactor = 5.0;

        /// <summary>The default relative tolerance, 1e-6.</summary>
        internal const double DefaultRelativeTolerance = 1e-6;

        /// <summary>The default absolute tolerance, 1e-9 (in each component's own unit: m, m/s, rad/s).</summary>
        internal const double DefaultAbsoluteTolerance = 1e-9;

        /// <summary>
        /// Creates the method with the given tolerances.
        /// </summary>
        /// <param name="relativeTolerance">rtol; finite, in [1e-15, 1].</param>
        /// <param name="absoluteTolerance">atol, in each component's unit (m, m/s, rad/s); finite and &gt; 0.</param>
        /// <exception cref="ArgumentOutOfRangeException">A tolerance is out of its range.</exception>
        public DormandPrince54(double relativeTolerance = DefaultRelativeTolerance, double absoluteTolerance = DefaultAbsoluteTolerance)
        {
            RelativeTolerance = Require.InRange(relativeTolerance, 1e-15, 1, nameof(relativeTolerance));
            AbsoluteTolerance = Require.Positive(absoluteTolerance, nameof(absoluteTolerance));
        }

        /// <summary>The method with the default tolerances (rtol 1e-6, atol 1e-9).</summary>
        public static DormandPrince54 Instance { get; } = new DormandPrince54();

        /// <summary>The relative tolerance rtol.</summary>
        internal double RelativeTolerance { get; }

        /// <summary>The absolute tolerance atol (m, m/s, rad/s per component).</summary>
        internal double AbsoluteTolerance { get; }

        /// <inheritdoc />
        string IIntegrator.Name => "dp54";

        /// <inheritdoc />
        int IIntegrator.Order => 5;

        /// <inheritdoc />
        int IIntegrator.DerivativeEvaluationsPerStep => 6;

        /// <summary>
        /// Takes one fixed step with the fifth-order solution (no error control). Six evaluations: k2..k6 and
        /// the end derivative k7 (k1 is passed in).
        /// </summary>
        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            DormandPrince54Stages stages = default;
            if (!FlightKernel.Of(model).DormandPrince54(state, derivative, step, ref stages))
            {
                GeneralStages(model, state, derivative, step, ref stages);
            }

            // First same as last: the seventh stage is the derivative at the fifth-order end.
            endDerivative = stages.K7;
            evaluations = 6;
            return stages.End;
        }

        /// <summary>
        /// Attempts one adaptive step of <paramref name="step"/> seconds from <paramref name="state"/>.
        /// Always costs six new evaluations (k2..k7). When the step is accepted, <paramref name="result"/>
        /// holds the end state, the end derivative (the next step's k1) and the dense output; when it is
        /// rejected, only <see cref="DormandPrince54Step.ErrorNorm"/> and <see cref="DormandPrince54Step.NextStep"/>
        /// are meaningful, and the caller retries from the same state with the smaller next step.
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The start state; every component finite.</param>
        /// <param name="derivative">FlightKernel.DerivativeOf(model, state).</param>
        /// <param name="step">The step to try, s; finite and &gt; 0.</param>
        /// <param name="result">The outcome (see above).</param>
        /// <returns>True when the estimated error is within the tolerances and the step was taken.</returns>
        /// <exception cref="ArgumentException">The state is not finite or the step is out of range.</exception>
        internal bool TryStep(FlightModel model, in FlightState state, in StateDerivative derivative, double step, out DormandPrince54Step result)
        {
            // Copied before result is cleared: state and derivative may be result's own Start and StartDerivative (a retry
            // from the rejected step's start, written over it).
            FlightState start = state;
            StateDerivative k1 = derivative;
            result = default;
            return TryStepInPlace(model, start, k1, step, ref result);
        }

        /// <summary>
        /// <see cref="TryStep(FlightModel, in FlightState, in StateDerivative, double, out DormandPrince54Step)"/> writing
        /// the step into <paramref name="result"/> in place (the flight core keeps one): no copy of the stages or of the step.
        /// </summary>
        internal bool TryStepInPlace(FlightModel model, in FlightState state, in StateDerivative derivative, double step, ref DormandPrince54Step result)
        {
            StepArguments.Check(model, state, step);
            result.Start = state;
            result.StartDerivative = derivative;
            // From here on the step's own copies of the start (the arguments may be the result's own fields).
            if (!FlightKernel.Of(model).DormandPrince54(result.Start, result.StartDerivative, step, ref result.Stages))
            {
                // A stage's rates may not be finite, so FlightModel.Derivative may take its scaled path: the step through it.
                GeneralStages(model, result.Start, result.StartDerivative, step, ref result.Stages);
            }

            return Finish(step, ref result);
        }

        /// <summary>
        /// <see cref="TryStep"/> with every stage through <see cref="FlightModel.Derivative"/> (not the model's kernel): the
        /// arithmetic the kernel's step reproduces, for the tests that hold it to it.
        /// </summary>
        internal bool TryStepThroughDerivative(FlightModel model, in FlightState state, in StateDerivative derivative, double step, out DormandPrince54Step result)
        {
            StepArguments.Check(model, state, step);
            FlightState start = state; // state and derivative may be result's own fields (see TryStep)
            StateDerivative k1 = derivative;
            result = default;
            result.Start = start;
            result.StartDerivative = k1;
            GeneralStages(model, result.Start, result.StartDerivative, step, ref result.Stages);
            return Finish(step, ref result);
        }

        // The error norm, the controller's next step and the dense output of a step whose stages are known.
        private bool Finish(double step, ref DormandPrince54Step result)
        {
            ref readonly DormandPrince54Stages stages = ref result.Stages;
            double norm = ErrorNorm(result.Start, stages.End, result.StartDerivative, stages.K3, stages.K4, stages.K5, stages.K6, stages.K7, step);
            bool accepted = norm <= 1.0 && stages.End.IsFinite;
            double factor;
            if (!double.IsFinite(norm))
            {
                factor = MinimumFactor;
            }
            else if (norm < 1.8e-4)
            {
                // 0.9 norm^(-1/5) > 5.04 here: the factor is clamped to 5 either way (no power needed).
                factor = MaximumFactor;
            }
            else if (norm > 2000)
            {
                // 0.9 norm^(-1/5) < 0.197 here: clamped to 0.2 either way.
                factor = MinimumFactor;
            }
            else
            {
                factor = Math.Max(MinimumFactor, Math.Min(MaximumFactor, Safety * PowMinusOneFifth(norm)));
            }

            if (!accepted)
            {
                factor = Math.Min(factor, 1.0);
            }

            result.Complete(step, norm, step * factor, accepted);
            return accepted;
        }

        /// <summary>
        /// The step the controller's error estimate asks for where <paramref name="step"/> began: its size times
        /// 0.9 norm^(-1/5), without the factor's limits (0.2 to 5 a step), which only pace the controller. +infinity for an
        /// error norm of zero (no error estimate limits the step), NaN for a step not accepted or not finite.
        /// </summary>
        internal static double StepAskedFor(in DormandPrince54Step step)
        {
            double norm = step.ErrorNorm;
            if (!step.Accepted || !(norm >= 0) || !(step.Step > 0))
            {
                return double.NaN;
            }

            // Below 1e-300 the power would exceed 1e60 times the step: nothing limits the step.
            return norm < 1e-300 ? double.PositiveInfinity : step.Step * (Safety * PowMinusOneFifth(norm));
        }

        /// <summary>
        /// x^(-1/5) for the controller's error norms (1.8e-4 to 2000, where the factor is not clamped; any x from 1e-300 to
        /// double.MaxValue works): sqrt(x'^(-2/5)) 2^k with x' = x 2^(5k) &gt;= 1, the power by <see cref="Aerodynamics.StepanekDrag.PowMinusTwoFifths"/>
        /// and both scalings by powers of two (exact): within 1.6 ulp of the true power (1.585 ulp the worst a review found
        /// against 200-bit arithmetic; the square root halves the 2/5 power's 2.05 ulp and adds its own half ulp), the same
        /// on every runtime (square roots are correctly rounded), and cheaper than
        /// <see cref="PortableMath.Pow"/>'s logarithm and exponential (about 6 % of an aim solve, docs/performance.md). Test
        /// <c>ControllerPower_IsWithinItsBoundOfTheTruePower</c>.
        /// </summary>
        internal static double PowMinusOneFifth(double x)
        {
            int k = 0;
            if (x < 1)
            {
                int e = (int)((BitConverter.DoubleToInt64Bits(x) >> 52) & 0x7FF) - 1023; // x normal: x >= 2^e
                k = (-e + 4) / 5;                                                         // 5k >= -e, so x 2^(5k) >= 1
                x *= BitConverter.Int64BitsToDouble((long)(1023 + 5 * k) << 52);
            }

            double y = Math.Sqrt(Aerodynamics.StepanekDrag.PowMinusTwoFifths(x));
            return k == 0 ? y : y * BitConverter.Int64BitsToDouble((long)(1023 + k) << 52);
        }

        /// <summary>
        /// A first step for <see cref="TryStep"/> from the tolerances and the local behaviour of the solution
        /// (Hairer, Norsett &amp; Wanner 1993, II.4 "Starting step size"): one extra evaluation.
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The start state; every component finite.</param>
        /// <param name="derivative">FlightKernel.DerivativeOf(model, state).</param>
        /// <param name="maximumStep">The largest step to return, s; finite and &gt; 0.</param>
        /// <returns>A step in (0, maximumStep].</returns>
        /// <exception cref="ArgumentException">The state is not finite or maximumStep is out of range.</exception>
        internal double InitialStep(FlightModel model, in FlightState state, in StateDerivative derivative, double maximumStep)
        {
            StepArguments.Check(model, state, maximumStep);
            double d0 = 0, d1 = 0;
            Accumulate(state, derivative, ref d0, ref d1);
            d0 = Math.Sqrt(d0 / 9);
            d1 = Math.Sqrt(d1 / 9);
            double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
            h0 = Math.Min(h0, maximumStep);

            FlightState trial = state.Advance(derivative, h0);
            StateDerivative f1 = FlightKernel.DerivativeOf(model, trial);
            double d2 = 0, unused = 0;
            Accumulate(state, Difference(f1, derivative), ref unused, ref d2);
            d2 = Math.Sqrt(d2 / 9) / h0;

            double largest = Math.Max(d1, d2);
            double h1 = largest <= 1e-15 ? Math.Max(1e-6, h0 * 1e-3) : PortableMath.Pow(0.01 / largest, 0.2);
            double h = Math.Min(100 * h0, h1);
            return double.IsFinite(h) && h > 0 ? Math.Min(h, maximumStep) : Math.Min(1e-6, maximumStep);
        }

        // The stages through FlightModel.Derivative, one call each (the arithmetic the kernel's step reproduces).
        internal static void GeneralStages(FlightModel model, in FlightState y, in StateDerivative k1, double h, ref DormandPrince54Stages stages)
        {
            Stages(model, y, k1, h, out StateDerivative k2, out StateDerivative k3, out StateDerivative k4, out StateDerivative k5, out StateDerivative k6);
            FlightState end = Combine(y, h, k1, k3, k4, k5, k6, B1, B3, B4, B5, B6, h);
            StateDerivative k7 = FlightKernel.DerivativeOf(model, end);
            stages.End = end;
            stages.K2.Set(k2);
            stages.K3.Set(k3);
            stages.K4.Set(k4);
            stages.K5.Set(k5);
            stages.K6.Set(k6);
            stages.K7 = k7;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Stages(
            FlightModel model,
            in FlightState y,
            in StateDerivative k1,
            double h,
            out StateDerivative k2,
            out StateDerivative k3,
            out StateDerivative k4,
            out StateDerivative k5,
            out StateDerivative k6)
        {
            k2 = FlightKernel.DerivativeOf(model, y.Advance(k1, A21 * h));
            k3 = FlightKernel.DerivativeOf(model, Combine(y, h, k1, k2, A31, A32, C3 * h));
            k4 = FlightKernel.DerivativeOf(model, Combine(y, h, k1, k2, k3, A41, A42, A43, C4 * h));
            k5 = FlightKernel.DerivativeOf(model, Combine(y, h, k1, k2, k3, k4, A51, A52, A53, A54, C5 * h));
            k6 = FlightKernel.DerivativeOf(model, Combine(y, h, k1, k2, k3, k4, k5, A61, A62, A63, A64, A65, h));
        }

        // y + h (a k_a + b k_b), with time advanced by dt.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static FlightState Combine(in FlightState y, double h, in StateDerivative ka, in StateDerivative kb, double a, double b, double dt)
        {
            double ha = h * a, hb = h * b;
            return new FlightState(
                y.Position + ka.Velocity * ha + kb.Velocity * hb,
                y.Velocity + ka.Acceleration * ha + kb.Acceleration * hb,
                y.AngularVelocity + ka.AngularAcceleration * ha + kb.AngularAcceleration * hb,
                y.Time + dt);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static FlightState Combine(
            in FlightState y, double h, in StateDerivative ka, in StateDerivative kb, in StateDerivative kc, double a, double b, double c, double dt)
        {
            double ha = h * a, hb = h * b, hc = h * c;
            return new FlightState(
                y.Position + ka.Velocity * ha + kb.Velocity * hb + kc.Velocity * hc,
                y.Velocity + ka.Acceleration * ha + kb.Acceleration * hb + kc.Acceleration * hc,
                y.AngularVelocity + ka.AngularAcceleration * ha + kb.AngularAcceleration * hb + kc.AngularAcceleration * hc,
                y.Time + dt);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static FlightState Combine(
            in FlightState y,
            double h,
            in StateDerivative ka,
            in StateDerivative kb,
            in StateDerivative kc,
            in StateDerivative kd,
            double a,
            double b,
            double c,
            double d,
            double dt)
        {
            double ha = h * a, hb = h * b, hc = h * c, hd = h * d;
            return new FlightState(
                y.Position + ka.Velocity * ha + kb.Velocity * hb + kc.Velocity * hc + kd.Velocity * hd,
                y.Velocity + ka.Acceleration * ha + kb.Acceleration * hb + kc.Acceleration * hc + kd.Acceleration * hd,
                y.AngularVelocity + ka.AngularAcceleration * ha + kb.AngularAcceleration * hb + kc.AngularAcceleration * hc +
                kd.AngularAcceleration * hd,
                y.Time + dt);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static FlightState Combine(
            in FlightState y,
            double h,
            in StateDerivative ka,
            in StateDerivative kb,
            in StateDerivative kc,
            in StateDerivative kd,
            in StateDerivative ke,
            double a,
            double b,
            double c,
            double d,
            double e,
            double dt)
        {
            double ha = h * a, hb = h * b, hc = h * c, hd = h * d, he = h * e;
            return new FlightState(
                y.Position + ka.Velocity * ha + kb.Velocity * hb + kc.Velocity * hc + kd.Velocity * hd + ke.Velocity * he,
                y.Velocity + ka.Acceleration * ha + kb.Acceleration * hb + kc.Acceleration * hc + kd.Acceleration * hd + ke.Acceleration * he,
                y.AngularVelocity + ka.AngularAcceleration * ha + kb.AngularAcceleration * hb + kc.AngularAcceleration * hc +
                kd.AngularAcceleration * hd + ke.AngularAcceleration * he,
                y.Time + dt);
        }

        private double ErrorNorm(
            in FlightState y0,
            in FlightState y1,
            in StateDerivative k1,
            in StageRates k3,
            in StageRates k4,
            in StageRates k5,
            in StageRates k6,
            in StateDerivative k7,
            double h)
        {
            // err = h (e1 k1 + e3 k3 + ... + e7 k7), component by component, scaled by atol + rtol max(|y0|, |y1|); summed as
            // the vector form sums it (position, velocity, spin; x, y, z), operation for operation. Scalars, not Vector3d
            // expressions: Mono's JIT zeroes, stores and copies every vector temporary (2,276 instructions here before).
            double sum =
                Scaled(k1.Velocity.X, k3.Velocity.X, k4.Velocity.X, k5.Velocity.X, k6.Velocity.X, k7.Velocity.X, h, y0.Position.X, y1.Position.X) +
                Scaled(k1.Velocity.Y, k3.Velocity.Y, k4.Velocity.Y, k5.Velocity.Y, k6.Velocity.Y, k7.Velocity.Y, h, y0.Position.Y, y1.Position.Y) +
                Scaled(k1.Velocity.Z, k3.Velocity.Z, k4.Velocity.Z, k5.Velocity.Z, k6.Velocity.Z, k7.Velocity.Z, h, y0.Position.Z, y1.Position.Z);
            sum +=
                Scaled(k1.Acceleration.X, k3.Acceleration.X, k4.Acceleration.X, k5.Acceleration.X, k6.Acceleration.X, k7.Acceleration.X, h, y0.Velocity.X, y1.Velocity.X) +
                Scaled(k1.Acceleration.Y, k3.Acceleration.Y, k4.Acceleration.Y, k5.Acceleration.Y, k6.Acceleration.Y, k7.Acceleration.Y, h, y0.Velocity.Y, y1.Velocity.Y) +
                Scaled(k1.Acceleration.Z, k3.Acceleration.Z, k4.Acceleration.Z, k5.Acceleration.Z, k6.Acceleration.Z, k7.Acceleration.Z, h, y0.Velocity.Z, y1.Velocity.Z);
            sum +=
                Scaled(k1.AngularAcceleration.X, k3.AngularAcceleration.X, k4.AngularAcceleration.X, k5.AngularAcceleration.X, k6.AngularAcceleration.X,
                    k7.AngularAcceleration.X, h, y0.AngularVelocity.X, y1.AngularVelocity.X) +
                Scaled(k1.AngularAcceleration.Y, k3.AngularAcceleration.Y, k4.AngularAcceleration.Y, k5.AngularAcceleration.Y, k6.AngularAcceleration.Y,
                    k7.AngularAcceleration.Y, h, y0.AngularVelocity.Y, y1.AngularVelocity.Y) +
                Scaled(k1.AngularAcceleration.Z, k3.AngularAcceleration.Z, k4.AngularAcceleration.Z, k5.AngularAcceleration.Z, k6.AngularAcceleration.Z,
                    k7.AngularAcceleration.Z, h, y0.AngularVelocity.Z, y1.AngularVelocity.Z);
            return Math.Sqrt(sum / 9);
        }

        // One component's scaled squared error: (h (e1 k1 + ... + e7 k7) / (atol + rtol max(|a|, |b|)))^2.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private double Scaled(double k1, double k3, double k4, double k5, double k6, double k7, double h, double a, double b)
        {
            double error = (k1 * E1 + k3 * E3 + k4 * E4 + k5 * E5 + k6 * E6 + k7 * E7) * h;
            double scaled = error / (AbsoluteTolerance + RelativeTolerance * Larger(Math.Abs(a), Math.Abs(b)));
            return scaled * scaled;
        }

        // Math.Max of two magnitudes (never -0) of which the first, the step's start, is finite: a NaN second is returned,
        // as Math.Max would, without Math.Max's NaN and signed-zero sequence (a dozen instructions on each of the nine).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Larger(double start, double end) => start > end ? start : end;

        // Sum over components of (y_i / sc_i)^2 into d0 and (f_i / sc_i)^2 into d1, with sc_i = atol + rtol |y0_i|.
        private void Accumulate(in FlightState y, in StateDerivative f, ref double d0, ref double d1)
        {
            Add(y.Position, f.Velocity, ref d0, ref d1);
            Add(y.Velocity, f.Acceleration, ref d0, ref d1);
            Add(y.AngularVelocity, f.AngularAcceleration, ref d0, ref d1);
        }

        private void Add(in Vector3d y, in Vector3d f, ref double d0, ref double d1)
        {
            double sx = AbsoluteTolerance + RelativeTolerance * Math.Abs(y.X);
            double sy = AbsoluteTolerance + RelativeTolerance * Math.Abs(y.Y);
            double sz = AbsoluteTolerance + RelativeTolerance * Math.Abs(y.Z);
            d0 += (y.X / sx) * (y.X / sx) + (y.Y / sy) * (y.Y / sy) + (y.Z / sz) * (y.Z / sz);
            d1 += (f.X / sx) * (f.X / sx) + (f.Y / sy) * (f.Y / sy) + (f.Z / sz) * (f.Z / sz);
        }

        private static StateDerivative Difference(in StateDerivative a, in StateDerivative b) =>
            new StateDerivative(a.Velocity - b.Velocity, a.Acceleration - b.Acceleration, a.AngularAcceleration - b.AngularAcceleration);
    }

    /// <summary>
    /// The stages of one Dormand-Prince 5(4) step: the fifth-order end state and k2..k7 (k7 is the derivative at the end,
    /// the next step's k1). The error estimate and dense output read the end and k3..k7 (k2 has weight zero in both); k2 is
    /// here because the later stages are formed from it. Plain fields, written in place by the flight kernel (it is part
    /// of a <see cref="DormandPrince54Step"/>).
    /// </summary>
    internal struct DormandPrince54Stages
    {
        public FlightState End;
        public StageRates K2;
        public StageRates K3;
        public StageRates K4;
        public StageRates K5;
        public StageRates K6;
        public StateDerivative K7;
    }

    /// <summary>
    /// Three vectors, one per part of the state (position, velocity, spin), named as a <see cref="StateDerivative"/>'s:
    /// the rates of one inner stage of a Dormand-Prince step (k2..k6), or one row of its dense output. Plain fields,
    /// written one by one: under Mono a <c>new StateDerivative(...)</c> stored into a field goes through a zero-filled
    /// 72-byte temporary (a call to memset) and a copy, eight times per step where these were StateDerivatives.
    /// </summary>
    internal struct StageRates
    {
        public Vector3d Velocity;
        public Vector3d Acceleration;
        public Vector3d AngularAcceleration;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Set(in Vector3d velocity, in Vector3d acceleration, in Vector3d angularAcceleration)
        {
            Velocity = velocity;
            Acceleration = acceleration;
            AngularAcceleration = angularAcceleration;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Set(in StateDerivative rates) => Set(rates.Velocity, rates.Acceleration, rates.AngularAcceleration);
    }
}
