using System;
using System.Runtime.CompilerServices;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    /// <summary>
    /// A fixed-step ODE stepper for <see cref="FlightModel"/>. Implementations are stateless, immutable,
    /// thread-safe and allocate nothing per step.
    /// </summary>
    /// <remarks>
    /// <para>Every method here starts from the derivative at the start of the step (k1 = f(y_n)) and returns the
    /// derivative at the end of the step together with the end state. A stepping loop passes the one back in as
    /// the other: the end derivative of one step is the start derivative of the next, and it is also what the
    /// cubic Hermite dense output needs at the step's end. So no point is evaluated twice, and a loop pays
    /// exactly the <c>evaluations</c> each step reports (<see cref="DerivativeEvaluationsPerStep"/> for the
    /// fixed methods; more for <see cref="StableIntegrator"/> when it substeps).</para>
    /// </remarks>
    public interface IIntegrator
    {
        /// <summary>A short, stable name: "euler", "semi-implicit-euler", "heun", "rk4", ...</summary>
        string Name { get; }

        /// <summary>The order of accuracy p: the global error falls as step^p.</summary>
        int Order { get; }

        /// <summary>
        /// Derivative evaluations one step costs when it does not substep, counting the end derivative it
        /// returns (the next step's k1) and not the start derivative passed in: 1 for the Euler methods, 2 for
        /// Heun, 4 for RK4, 6 for Dormand-Prince 5(4).
        /// </summary>
        int DerivativeEvaluationsPerStep { get; }

        /// <summary>Advances <paramref name="state"/> by <paramref name="step"/> seconds.</summary>
        /// <param name="model">The flight model (the right-hand side).</param>
        /// <param name="state">The state at the start of the step; every component finite.</param>
        /// <param name="derivative">The derivative at the start of the step: model.Derivative(state), or the previous step's
        /// <paramref name="endDerivative"/> (not checked: it is the model's, finite for any finite state whose forces fit in a
        /// double; a non-finite one gives a non-finite result, which the flight core refuses).</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="endDerivative">The derivative at the returned state (evaluated once, here), to pass into the next step. The
        /// built-in methods evaluate the model through a kernel specialised for its laws: model.Derivative's bits, except to
        /// rounding where the kernel folds a constant lift or Stepanek's lift.</param>
        /// <param name="evaluations">The model evaluations this call made, the end derivative included.</param>
        /// <returns>The state at time state.Time + step. A step far beyond the method's stability limit can
        /// return a non-finite state or derivative; the caller decides (the flight core refuses such a step).</returns>
        /// <exception cref="ArgumentException">
        /// The state is not finite or the step is not finite and positive (checked before any work).
        /// </exception>
        FlightState Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations);
    }

    /// <summary>Conveniences over <see cref="IIntegrator"/> for a single step outside a stepping loop.</summary>
    internal static class IntegratorExtensions
    {
        /// <summary>
        /// Advances <paramref name="state"/> by <paramref name="step"/> seconds, evaluating the start derivative
        /// itself and discarding the end derivative. For one step; a loop should call
        /// <see cref="IIntegrator.Step"/> and pass each end derivative on (as the flight core does).
        /// </summary>
        /// <param name="integrator">The method.</param>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The start state; every component finite.</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <exception cref="ArgumentException">The state is not finite or the step is out of range.</exception>
        public static FlightState Step(this IIntegrator integrator, FlightModel model, in FlightState state, double step)
        {
            Require.NotNull(integrator, nameof(integrator));
            StepArguments.Check(model, state, step);
            return integrator.Step(model, state, FlightKernel.DerivativeOf(model, state), step, out _, out _);
        }

        /// <summary>
        /// Advances <paramref name="state"/> by <paramref name="step"/> seconds from its known start derivative,
        /// discarding the end derivative (one evaluation a loop would reuse). For one step.
        /// </summary>
        /// <param name="integrator">The method.</param>
        /// <param name="model">The flight model.</param>
        /// <param name="state">The start state; every component finite.</param>
        /// <param name="derivative">The derivative at the start: model.Derivative(state), or the previous step's end derivative.</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <exception cref="ArgumentException">The state is not finite or the step is out of range.</exception>
        public static FlightState Step(this IIntegrator integrator, FlightModel model, in FlightState state, in StateDerivative derivative, double step)
        {
            Require.NotNull(integrator, nameof(integrator));
            return integrator.Step(model, state, derivative, step, out _, out _);
        }
    }

    /// <summary>The integrators the library ships, by name.</summary>
    public static class Integrators
    {
        /// <summary>
        /// Every integrator usable at a fixed step, lowest order first: the four classic methods, Dormand-Prince
        /// 5(4) at a fixed step ("dp54", its fifth-order solution) and the safe default
        /// <see cref="StableIntegrator.RungeKutta4"/> ("stable-rk4"). A new array on each call.
        /// </summary>
        internal static IIntegrator[] All => new IIntegrator[]
        {
            ExplicitEuler.Instance, SemiImplicitEuler.Instance, Heun.Instance, RungeKutta4.Instance,
            DormandPrince54.Instance, StableIntegrator.RungeKutta4,
        };

        /// <summary>The names <see cref="FromName"/> accepts (a new array on each call).</summary>
        public static string[] Names
        {
            get
            {
                IIntegrator[] all = All;
                var names = new string[all.Length];
                for (int i = 0; i < all.Length; i++)
                {
                    names[i] = all[i].Name;
                }

                return names;
            }
        }

        /// <summary>The integrator called <paramref name="name"/> (case-insensitive; '_' or ' ' may stand for '-').</summary>
        /// <param name="name">One of <see cref="Names"/>.</param>
        /// <exception cref="ArgumentException">The name is unknown; the message lists the known names.</exception>
        public static IIntegrator FromName(string name)
        {
            foreach (IIntegrator integrator in All)
            {
                if (NameLookup.Matches(integrator.Name, name))
                {
                    return integrator;
                }
            }

            throw new ArgumentException(
                $"integrator must be one of {string.Join(", ", Names)}; got '{name ?? "null"}'.", nameof(name));
        }
    }

    /// <summary>The argument checks every integrator makes before it does any work.</summary>
    internal static class StepArguments
    {
        // The common case in one branch: x - x is 0 for every finite x and NaN otherwise, so the sum is 0 exactly when
        // all ten numbers are finite (no sum of finite terms can overflow: every term is 0). Inlined into each Step.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void Check(FlightModel model, in FlightState state, double step)
        {
            Vector3d p = state.Position, v = state.Velocity, w = state.AngularVelocity;
            double zero = (p.X - p.X) + (p.Y - p.Y) + (p.Z - p.Z) + (v.X - v.X) + (v.Y - v.Y) + (v.Z - v.Z) +
                (w.X - w.X) + (w.Y - w.Y) + (w.Z - w.Z) + (state.Time - state.Time);
            if (model is null || !(step > 0) || !(step <= double.MaxValue) || zero != 0)
            {
                Throw(model, state, step);
            }
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static void Throw(FlightModel? model, in FlightState state, double step)
        {
            if (model is null)
            {
                throw new ArgumentNullException(nameof(model), "model must not be null.");
            }

            if (!double.IsFinite(step) || step <= 0)
            {
                throw new ArgumentOutOfRangeException(
                    nameof(step), step, $"step must be a finite time step > 0 s; got {Require.Format(step)}.");
            }

            // Called only when a check failed: with the model and the step valid, it is the state.
            Require.FiniteState(state, nameof(state));
        }
    }
}
