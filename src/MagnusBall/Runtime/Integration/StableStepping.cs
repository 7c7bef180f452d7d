using System;
using MagnusBall.Aerodynamics;

namespace MagnusBall.Integration
{
    /// <summary>
    /// Stability-safe stepping, the work of <see cref="StableIntegrator"/> (whose remarks give the criterion): splits
    /// a step into substeps short enough that explicit integration of quadratic drag (and Magnus lift) cannot blow up.
    /// </summary>
    internal static class StableStepping
    {
        public const double DefaultStiffnessLimit = StableIntegrator.DefaultStiffnessLimit;

        public const int MaximumSubsteps = StableIntegrator.MaximumSubsteps;

        /// <summary>
        /// The stiffness rate sigma, 1/s (see the class remarks): an upper estimate of the largest decay or rotation
        /// rate of the linearised flight over a step of <paramref name="step"/> seconds from <paramref name="state"/>.
        /// Zero in a vacuum without spin decay. Costs no derivative evaluation: one or two evaluations of each coefficient law.
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The state; every component finite.</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <exception cref="ArgumentException">A state component is not finite or the step is out of range.</exception>
        public static double StiffnessRate(FlightModel model, in FlightState state, double step)
        {
            StepArguments.Check(model, state, step);
            return model.StiffnessRate(state, step);
        }

        /// <summary>
        /// The number of equal substeps that keeps h_sub sigma within <paramref name="stiffnessLimit"/> over a step of
        /// <paramref name="step"/> seconds, judged at the start of the step: ceil(step sigma / limit), at least 1.
        /// <see cref="Step(IIntegrator, FlightModel, in FlightState, in StateDerivative, double, out StateDerivative, out int, double)"/> re-judges at every substep and may take fewer.
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The state; every component finite.</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="stiffnessLimit">The bound on h_sub sigma; finite, in (0, 2.5].</param>
        /// <exception cref="ArgumentException">An argument is out of range (the message names it).</exception>
        public static int SubstepCount(
            FlightModel model, in FlightState state, double step, double stiffnessLimit = DefaultStiffnessLimit)
        {
            StepArguments.Check(model, state, step);
            CheckLimit(stiffnessLimit);
            return Count(step * model.StiffnessRate(state, step) / stiffnessLimit);
        }

        /// <summary>
        /// Advances <paramref name="state"/> by <paramref name="step"/> seconds with <paramref name="integrator"/>, in as
        /// many substeps as stability needs (one in the common case), at most <see cref="MaximumSubsteps"/>. Allocates nothing.
        /// </summary>
        /// <param name="integrator">The fixed-step method.</param>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The start state; every component finite.</param>
        /// <param name="derivative">model.Derivative(state).</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="endDerivative">model.Derivative of the returned state: the next step's start derivative and
        /// the end slope a cubic Hermite over the whole step needs.</param>
        /// <param name="substeps">How many substeps were taken (evaluations: substeps x the integrator's per-step count).</param>
        /// <param name="stiffnessLimit">The bound on h_sub sigma; finite, in (0, 2.5]. The default, 1, is stable and
        /// accurate for every shipped integrator.</param>
        /// <returns>The state at state.Time + step. When even <see cref="MaximumSubsteps"/> substeps are too long (a
        /// finite but absurd state, such as a speed of 1e150 m/s), the step is taken in that many and may come out
        /// non-finite: the flight core then refuses it as diverged.</returns>
        /// <exception cref="ArgumentException">An argument is out of range (the message names it).</exception>
        public static FlightState Step(
            IIntegrator integrator,
            FlightModel model,
            in FlightState state,
            in StateDerivative derivative,
            double step,
            out StateDerivative endDerivative,
            out int substeps,
            double stiffnessLimit = DefaultStiffnessLimit) =>
            Step(integrator, model, state, derivative, step, out endDerivative, out substeps, out _, stiffnessLimit);

        /// <summary>The step of the public overload, also reporting the model evaluations made (the end derivative included).</summary>
        internal static FlightState Step(
            IIntegrator integrator,
            FlightModel model,
            in FlightState state,
            in StateDerivative derivative,
            double step,
            out StateDerivative endDerivative,
            out int substeps,
            out int evaluations,
            double stiffnessLimit)
        {
            Require.NotNull(integrator, nameof(integrator));
            StepArguments.Check(model, state, step);
            CheckLimit(stiffnessLimit);

            double endTime = state.Time + step;
            FlightState current = state;
            StateDerivative slope = derivative;
            substeps = 0;
            evaluations = 0;
            double remaining = step;
            // Bounded: every pass takes one substep, and the total is capped at MaximumSubsteps.
            while (true)
            {
                // The common case without evaluating the laws: a bound shows h sigma below half the limit, so the count is
                // 1, as the exact rate gives (it is at most the bound, and Count gives 1 up to the whole limit).
                int count = SubstepsFor(model, current, remaining, stiffnessLimit);
                if (substeps + count > MaximumSubsteps)
                {
                    count = Math.Max(1, MaximumSubsteps - substeps);
                }

                double h = count == 1 ? remaining : remaining / count;
                substeps++;
                FlightState next = integrator.Step(model, current, slope, h, out slope, out int used);
                evaluations += used;
                if (count == 1)
                {
                    endDerivative = slope;
                    return new FlightState(next.Position, next.Velocity, next.AngularVelocity, endTime);
                }

                current = next;
                remaining = endTime - current.Time;
                if (!(remaining > 0) || !current.IsFinite)
                {
                    endDerivative = slope;
                    return new FlightState(current.Position, current.Velocity, current.AngularVelocity, endTime);
                }
            }
        }

        /// <summary>
        /// The substeps <see cref="Step(IIntegrator, FlightModel, in FlightState, in StateDerivative, double, out StateDerivative, out int, out int, double)"/>
        /// splits <paramref name="remaining"/> seconds from <paramref name="state"/> into (before its cap): 1 without
        /// evaluating the laws where a bound shows h sigma below half the limit (the exact rate then gives 1 too),
        /// otherwise ceil(h sigma / limit). Where it is 1 for the whole step, the step is the inner method's one step over
        /// it with the time set to its end: <c>FlightStepper.TryStep</c> takes that case of the stable RK4
        /// straight to the kernel, through this same method.
        /// </summary>
        internal static int SubstepsFor(FlightModel model, in FlightState state, double remaining, double stiffnessLimit) =>
            model.StiffnessSurelyBelow(state, remaining, 0.5 * stiffnessLimit)
                ? 1
                : Count(remaining * model.StiffnessRate(state, remaining) / stiffnessLimit);

        private static int Count(double ratio)
        {
            if (!(ratio > 1))
            {
                return 1;
            }

            return ratio >= MaximumSubsteps ? MaximumSubsteps : (int)Math.Ceiling(ratio);
        }

        private static void CheckLimit(double stiffnessLimit)
        {
            if (!double.IsFinite(stiffnessLimit) || stiffnessLimit <= 0 || stiffnessLimit > 2.5)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(stiffnessLimit), stiffnessLimit, $"stiffnessLimit must be in (0, 2.5]; got {Require.Format(stiffnessLimit)}.");
            }
        }
    }

    /// <summary>
    /// An <see cref="IIntegrator"/> that steps another one in as many substeps as stability needs: same results as the
    /// inner method where its step is already stable, substeps where it would not be. Drop it in wherever an
    /// <see cref="IIntegrator"/> is taken (a fixed-step driver, a predictor) to make large steps and light, fast balls
    /// safe: explicit integration of quadratic drag (and Magnus lift) then cannot blow up, whatever the ball, its speed
    /// or the step the caller asks for.
    /// </summary>
    /// <remarks>
    /// <para><b>Why.</b> Drag decelerates at k C_D s^2 (k = rho A / 2m).
    /// Linearised about the flight, its Jacobian has the eigenvalue -2 k C_D s along the velocity and -k C_D s
    /// across it; Magnus lift adds a rotation of rate about k |C_L| s. An explicit method is stable only while
    /// h |lambda| stays inside its stability region: 2 for explicit and semi-implicit Euler and Heun, 2.785 for
    /// RK4, 3.3 for Dormand-Prince; so a step beyond about 1/(k C_D s) makes the speed oscillate and, past it,
    /// grow without bound (measured in docs/integrators.md). A light ball at high speed (a table-tennis ball or a
    /// beach ball at 100 m/s) reaches that limit at steps of 1-70 ms, shorter than a frame hitch.</para>
    /// <para><b>The criterion.</b> The stiffness rate is sigma = max over x in {s, s_max} of
    /// 2 k x (C_D(x) + |C_L(x)|) + |dw/dt|(x) / |w| (when s_max &lt;= 1.1 s, 1.1 times its value at s_max alone), where s is the air-relative speed, s_max = s + |g| h the fastest
    /// the ball can go within the step, the coefficients are the model's own laws evaluated with the whole spin taken
    /// as transverse (the most lift the spin can give, whichever way the flight turns within the step), and the last
    /// term is the spin-decay rate. 2 k C_D s is the largest drag eigenvalue, 2 k |C_L| s bounds the Magnus rotation
    /// and its rank-one part. Substeps are chosen so that h_sub sigma &lt;= <see cref="StableIntegrator.DefaultStiffnessLimit"/> (1):
    /// h k C_D s &lt;= 1/2, half the measured oscillation limit of the Euler methods (h k C_D s = 1), a quarter or less of
    /// the measured divergence limits (2 for Euler and Heun, 2.45 for RK4, 1.41 for Dormand-Prince), and accurate:
    /// RK4's decay factor at h lambda = -1 is 0.375 against the exact 0.368. The rate is re-evaluated at the start of
    /// every substep, so substeps lengthen as the ball slows; a ball that sheds its speed from s0 to s1 takes about
    /// 2 ln(s0 / s1) / limit substeps beyond the ones the step itself needs.</para>
    /// <para><b>Limits.</b> Explicit and semi-implicit Euler and Heun amplify rotations (|1 + i x| &gt; 1): with Magnus
    /// lift much stronger than drag they gain speed however short the substep. The criterion makes them safe against
    /// drag, not against such lift; RK4 and Dormand-Prince, whose stability regions hold part of the imaginary axis,
    /// are safe against both. Hence <see cref="StableIntegrator.RungeKutta4"/> is the default.</para>
    /// <para>In the common case (a tennis ball at 1/240 s: h sigma ~ 0.003) a step is one substep and costs
    /// exactly what the integrator costs.</para>
    /// </remarks>
    public sealed class StableIntegrator : IIntegrator
    {
        /// <summary>Wraps <paramref name="inner"/>.</summary>
        /// <param name="inner">The method to substep.</param>
        /// <param name="stiffnessLimit">The bound on h_sub sigma; finite, in (0, 2.5] (see the remarks).</param>
        /// <exception cref="ArgumentException">inner is null or the limit is out of range.</exception>
        public StableIntegrator(IIntegrator inner, double stiffnessLimit = DefaultStiffnessLimit)
        {
            Inner = Require.NotNull(inner, nameof(inner));
            if (!double.IsFinite(stiffnessLimit) || stiffnessLimit <= 0 || stiffnessLimit > 2.5)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(stiffnessLimit), stiffnessLimit, $"stiffnessLimit must be in (0, 2.5]; got {Require.Format(stiffnessLimit)}.");
            }

            StiffnessLimit = stiffnessLimit;
            _name = "stable-" + inner.Name;
        }

        /// <summary>The default bound on h_sub sigma (see the remarks): 1.</summary>
        internal const double DefaultStiffnessLimit = 1.0;

        /// <summary>The most substeps one step takes before it gives up subdividing (a guard, never reached by physical
        /// input): such a step may come out non-finite, and the flight core then refuses it as diverged.</summary>
        internal const int MaximumSubsteps = 10_000;

        /// <summary>
        /// <paramref name="method"/> substepped only past its own stability bound on the real axis: h sigma at most 2 for the
        /// Euler methods and Heun, and 2.5 (the most this class takes; RK4's bound is 2.785, Dormand-Prince's 3.3) for the
        /// others. Its <see cref="SubstepCount"/> is 1 exactly when a fixed step of <paramref name="method"/> is within the
        /// bound for the flight's drag, so a caller can refuse or flag an unstable step before taking it (the CLI refuses it,
        /// the playground marks the flight unreliable). Null for a <see cref="StableIntegrator"/>, which splits its steps itself.
        /// </summary>
        /// <param name="method">The method a fixed step is taken with.</param>
        /// <exception cref="ArgumentNullException"><paramref name="method"/> is null.</exception>
        public static StableIntegrator? AtStabilityBound(IIntegrator method) => Require.NotNull(method, nameof(method)) switch
        {
            StableIntegrator => null,
            ExplicitEuler or SemiImplicitEuler or Heun => new StableIntegrator(method, 2.0),
            _ => new StableIntegrator(method, 2.5),
        };

        /// <summary>RK4 made stability-safe: the recommended default for a game's fixed step.</summary>
        public static StableIntegrator RungeKutta4 { get; } = new StableIntegrator(Integration.RungeKutta4.Instance);

        /// <summary>The wrapped method.</summary>
        internal IIntegrator Inner { get; }

        /// <summary>The bound on h_sub sigma.</summary>
        internal double StiffnessLimit { get; }

        /// <summary>"stable-" followed by the inner method's name, e.g. "stable-rk4".</summary>
        string IIntegrator.Name => _name;

        private readonly string _name;

        /// <inheritdoc />
        int IIntegrator.Order => Inner.Order;

        /// <summary>The inner method's count: the cost of a step that needs no substeps (each substep costs as much).</summary>
        int IIntegrator.DerivativeEvaluationsPerStep => Inner.DerivativeEvaluationsPerStep;

        /// <summary>
        /// The number of equal substeps that keeps h_sub sigma within <see cref="StiffnessLimit"/> over a step of
        /// <paramref name="step"/> seconds from <paramref name="state"/>, judged at the start of the step:
        /// ceil(step sigma / limit), at least 1, at most <see cref="MaximumSubsteps"/>. <see cref="IIntegrator.Step"/> re-judges at
        /// every substep and may take fewer. Costs no derivative evaluation (one or two evaluations of each coefficient law).
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The state; every component finite.</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <exception cref="ArgumentException">An argument is out of range (the message names it).</exception>
        public int SubstepCount(FlightModel model, in FlightState state, double step) =>
            StableStepping.SubstepCount(model, state, step, StiffnessLimit);

        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations) =>
            StableStepping.Step(Inner, model, state, derivative, step, out endDerivative, out _, out evaluations, StiffnessLimit);
    }
}
