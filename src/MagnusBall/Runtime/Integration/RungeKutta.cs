using System.Runtime.CompilerServices;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    /// <summary>
    /// Heun's method (explicit trapezoid, RK2): a full Euler predictor, then the average of the two slopes.
    /// Second order, two evaluations per step. Exact for the vacuum parabola.
    /// </summary>
    public sealed class Heun : IIntegrator
    {
        /// <summary>The shared instance (the method is stateless).</summary>
        public static Heun Instance { get; } = new Heun();

        /// <summary>
        /// Creates the method. It holds no state, so every instance steps exactly as <see cref="Instance"/> does.
        /// </summary>
        internal Heun()
        {
        }

        /// <inheritdoc />
        string IIntegrator.Name => "heun";

        /// <inheritdoc />
        int IIntegrator.Order => 2;

        /// <inheritdoc />
        int IIntegrator.DerivativeEvaluationsPerStep => 2;

        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            evaluations = 2;
            return FlightKernel.Of(model).Heun(state, derivative, step, out endDerivative);
        }
    }

    /// <summary>
    /// The classic fourth-order Runge-Kutta method: four evaluations per step, global error falling as h^4.
    /// The seed thesis's default method (Agrawal 2023, section 3).
    /// </summary>
    public sealed class RungeKutta4 : IIntegrator
    {
        /// <summary>The shared instance (the method is stateless).</summary>
        public static RungeKutta4 Instance { get; } = new RungeKutta4();

        /// <summary>
        /// Creates the method. It holds no state, so every instance steps exactly as <see cref="Instance"/> does.
        /// </summary>
        internal RungeKutta4()
        {
        }

        /// <inheritdoc />
        string IIntegrator.Name => "rk4";

        /// <inheritdoc />
        int IIntegrator.Order => 4;

        /// <inheritdoc />
        int IIntegrator.DerivativeEvaluationsPerStep => Evaluations;

        // The model evaluations of one step.
        internal const int Evaluations = 4;

        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            evaluations = Evaluations;
            return FlightKernel.Of(model).RungeKutta4(state, derivative, step, out endDerivative);
        }

        /// <summary>
        /// The most steps one <see cref="Advance"/> call takes: 250,000, that is 1,000,000 model evaluations, the cap of one
        /// prediction (<c>TrajectoryPredictor.MaxEvaluationsPerPrediction</c>): 17 minutes of flight at 1/240 s,
        /// about 11 ms of work on the thesis model and 60 ms on the full tennis model on the machine of docs/performance.md.
        /// </summary>
        internal const int MaximumAdvanceSteps = 250_000;

        /// <summary>
        /// Takes <paramref name="count"/> steps of <paramref name="step"/> seconds in one call, in place: the same bits as
        /// <paramref name="count"/> calls of <see cref="IIntegrator.Step"/>, each passing its end derivative on, with the arguments
        /// checked once and no call per step (docs/performance.md: 480 steps on the thesis model in 0.54x the time of the
        /// thesis-style code, against 0.65x for a loop of <see cref="IIntegrator.Step"/> calls on .NET). For one step a frame, a count of
        /// 1 is the cheaper call on .NET (0.57x: the state and derivative are updated in place, so the caller copies no end
        /// derivative) and <see cref="IIntegrator.Step"/> under Mono (0.58x against 0.77x). No events: for landings, bounces and samples use the flight core
        /// (<c>FlightStepper</c>, <c>FixedStepDriver</c>, <c>TrajectoryPredictor</c>).
        /// </summary>
        /// <remarks>
        /// <paramref name="derivative"/> must be FlightKernel.DerivativeOf(model, state): it is not checked, and a stale one (default, or
        /// the derivative before the game moved the ball, bounced or kicked it) gives a wrong first step without any error.
        /// After changing the state yourself, evaluate FlightKernel.DerivativeOf(model, state) again. A return value below
        /// <paramref name="count"/> means the flight diverged; check it.
        /// </remarks>
        /// <param name="model">The flight model (the right-hand side).</param>
        /// <param name="state">On entry the start state, every component finite; on return the state after the steps taken.</param>
        /// <param name="derivative">On entry FlightKernel.DerivativeOf(model, state); on return the derivative at the returned state (pass
        /// both into the next call).</param>
        /// <param name="step">The step, s; finite and &gt; 0.</param>
        /// <param name="count">The steps to take, 0 to <see cref="MaximumAdvanceSteps"/>.</param>
        /// <returns>The steps taken: <paramref name="count"/>, or fewer where the next step would have given a non-finite state
        /// or derivative (a step far beyond RK4's stability limit, or forces past the range of a double). Then
        /// <paramref name="state"/> and <paramref name="derivative"/> are the last finite ones, and state.Time tells how far they
        /// got. 4 model evaluations per step taken (and 4 for the step declined).</returns>
        /// <exception cref="System.ArgumentNullException"><paramref name="model"/> is null.</exception>
        /// <exception cref="System.ArgumentOutOfRangeException"><paramref name="step"/> is not finite and positive, or
        /// <paramref name="count"/> is outside 0 to <see cref="MaximumAdvanceSteps"/>.</exception>
        /// <exception cref="System.ArgumentException"><paramref name="state"/> is not finite. Every argument is checked before
        /// any work: when one is refused, <paramref name="state"/> and <paramref name="derivative"/> are unchanged.</exception>
        internal int Advance(FlightModel model, ref FlightState state, ref StateDerivative derivative, double step, int count)
        {
            StepArguments.Check(model, state, step);
            if (count < 0 || count > MaximumAdvanceSteps)
            {
                throw new System.ArgumentOutOfRangeException(
                    nameof(count), count, $"count must be in [0, {MaximumAdvanceSteps}] steps; got {count}.");
            }

            return FlightKernel.Of(model).RungeKutta4Advance(ref state, ref derivative, step, count);
        }

        /// <summary>
        /// <see cref="IIntegrator.Step"/> without its argument check, for the flight core, whose state is finite (it takes no other)
        /// and whose step it has checked itself: four evaluations, no interface call, and the end written straight into
        /// <paramref name="next"/> and <paramref name="endDerivative"/> (the core's fields; <paramref name="next"/> must
        /// not be a part of <paramref name="state"/>, see <see cref="FlightKernel.RungeKutta4Into"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void StepCheckedInto(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step, out FlightState next, out StateDerivative endDerivative) =>
            FlightKernel.Of(model).RungeKutta4Into(state, derivative, step, out next, out endDerivative);
    }
}
