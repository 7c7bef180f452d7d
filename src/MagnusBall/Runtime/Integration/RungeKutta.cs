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
            StateDerivative k2 = model.Derivative(state.Advance(derivative, step));
            double half = 0.5 * step;
            var end = new FlightState(
                state.Position + (derivative.Velocity + k2.Velocity) * half,
                state.Velocity + (derivative.Acceleration + k2.Acceleration) * half,
                state.AngularVelocity + (derivative.AngularAcceleration + k2.AngularAcceleration) * half,
                state.Time + step);
            endDerivative = model.Derivative(end);
            evaluations = 2;
            return end;
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

        /// <inheritdoc />
        public string Name => "rk4";

        /// <inheritdoc />
        public int Order => 4;

        /// <inheritdoc />
        public int DerivativeEvaluationsPerStep => 4;

        /// <inheritdoc />
        public FlightState Step(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step,
            out StateDerivative endDerivative, out int evaluations)
        {
            StepArguments.Check(model, state, step);
            double half = 0.5 * step;
            StateDerivative k2 = model.Derivative(state.Advance(derivative, half));
            StateDerivative k3 = model.Derivative(state.Advance(k2, half));
            StateDerivative k4 = model.Derivative(state.Advance(k3, step));
            double sixth = step / 6.0;
            var end = new FlightState(
                state.Position + (derivative.Velocity + 2.0 * (k2.Velocity + k3.Velocity) + k4.Velocity) * sixth,
                state.Velocity + (derivative.Acceleration + 2.0 * (k2.Acceleration + k3.Acceleration) + k4.Acceleration) * sixth,
                state.AngularVelocity +
                (derivative.AngularAcceleration + 2.0 * (k2.AngularAcceleration + k3.AngularAcceleration) + k4.AngularAcceleration) * sixth,
                state.Time + step);
            endDerivative = model.Derivative(end);
            evaluations = 4;
            return end;
        }
    }
}
