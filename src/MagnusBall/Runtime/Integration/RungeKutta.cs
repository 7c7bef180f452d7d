using System.Runtime.CompilerServices;

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
        public Heun()
        {
        }

        /// <inheritdoc />
        public string Name => "heun";

        /// <inheritdoc />
        public int Order => 2;

        /// <inheritdoc />
        public int DerivativeEvaluationsPerStep => 2;

        /// <inheritdoc />
        public FlightState Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            evaluations = 2;
            return model.Kernel.Heun(state, derivative, step, out endDerivative);
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
        public RungeKutta4()
        {
        }

        /// <inheritdoc />
        public string Name => "rk4";

        /// <inheritdoc />
        public int Order => 4;

        /// <inheritdoc />
        public int DerivativeEvaluationsPerStep => Evaluations;

        // The model evaluations of one step.
        internal const int Evaluations = 4;

        /// <inheritdoc />
        public FlightState Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            evaluations = Evaluations;
            return model.Kernel.RungeKutta4(state, derivative, step, out endDerivative);
        }

        /// <summary>
        /// <see cref="Step"/> without its argument check, for the flight core, whose state is finite (it takes no other)
        /// and whose step it has checked itself: four evaluations, no interface call, and the end written straight into
        /// <paramref name="next"/> and <paramref name="endDerivative"/> (the core's fields; <paramref name="next"/> must
        /// not be a part of <paramref name="state"/>, see <see cref="FlightKernel.RungeKutta4Into"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void StepCheckedInto(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step, out FlightState next, out StateDerivative endDerivative) =>
            model.Kernel.RungeKutta4Into(state, derivative, step, out next, out endDerivative);
    }
}
