using MagnusBall.Integration.Kernels;

namespace MagnusBall.Integration
{
    /// <summary>
    /// Explicit (forward) Euler, y_{n+1} = y_n + h f(y_n): first order, one evaluation per step. The seed
    /// thesis's first method (Agrawal 2023, section 3). In a vacuum it is exact in velocity and lags the
    /// parabola by g h t / 2 in position; it adds energy (about |a|^2 h^2 / 2 per unit mass each step).
    /// </summary>
    public sealed class ExplicitEuler : IIntegrator
    {
        /// <summary>The shared instance (the method is stateless).</summary>
        public static ExplicitEuler Instance { get; } = new ExplicitEuler();

        /// <summary>
        /// Creates the method. It holds no state, so every instance steps exactly as <see cref="Instance"/> does.
        /// </summary>
        internal ExplicitEuler()
        {
        }

        /// <inheritdoc />
        string IIntegrator.Name => "euler";

        /// <inheritdoc />
        int IIntegrator.Order => 1;

        /// <inheritdoc />
        int IIntegrator.DerivativeEvaluationsPerStep => 1;

        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            FlightState end = state.Advance(derivative, step);
            endDerivative = FlightKernel.DerivativeOf(model, end);
            evaluations = 1;
            return end;
        }
    }

    /// <summary>
    /// Semi-implicit (symplectic) Euler, the game-engine default: v_{n+1} = v_n + h a(y_n), then
    /// p_{n+1} = p_n + h v_{n+1}. First order, one evaluation per step; in a vacuum it loses energy
    /// rather than gaining it.
    /// </summary>
    public sealed class SemiImplicitEuler : IIntegrator
    {
        /// <summary>The shared instance (the method is stateless).</summary>
        public static SemiImplicitEuler Instance { get; } = new SemiImplicitEuler();

        /// <summary>
        /// Creates the method. It holds no state, so every instance steps exactly as <see cref="Instance"/> does.
        /// </summary>
        internal SemiImplicitEuler()
        {
        }

        /// <inheritdoc />
        string IIntegrator.Name => "semi-implicit-euler";

        /// <inheritdoc />
        int IIntegrator.Order => 1;

        /// <inheritdoc />
        int IIntegrator.DerivativeEvaluationsPerStep => 1;

        /// <inheritdoc />
        FlightState IIntegrator.Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            Vector3d velocity = state.Velocity + derivative.Acceleration * step;
            var end = new FlightState(
                state.Position + velocity * step,
                velocity,
                state.AngularVelocity + derivative.AngularAcceleration * step,
                state.Time + step);
            endDerivative = FlightKernel.DerivativeOf(model, end);
            evaluations = 1;
            return end;
        }
    }
}
