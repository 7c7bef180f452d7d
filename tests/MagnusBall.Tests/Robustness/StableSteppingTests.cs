using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Tests.Robustness
{
    /// <summary>The stability criterion: what it costs in the common case, what it does at the extremes, its arguments.</summary>
    [TestFixture]
    public class StableSteppingTests
    {
        private static FlightModel Tennis() =>
            new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));

        private static FlightState Drive() =>
            new FlightState(new Vector3d(0, 0, 1), new Vector3d(39.8, 0, 4.2), new Vector3d(0, 260, 0));

        [Test]
        public void CommonCase_IsOneSubstep_AndExactlyTheInnerStep()
        {
            FlightModel model = Tennis();
            FlightState state = Drive();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
            FlightState safe = StableStepping.Step(RungeKutta4.Instance, model, state, k1, 1.0 / 240, out StateDerivative end, out int substeps);
            FlightState raw = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k1, 1.0 / 240);

            Assert.That(substeps, Is.EqualTo(1));
            Assert.That(safe.Position, Is.EqualTo(raw.Position));
            Assert.That(safe.Velocity, Is.EqualTo(raw.Velocity));
            Assert.That(end.Acceleration, Is.EqualTo(FlightKernel.DerivativeOf(model, safe).Acceleration), "the end derivative is handed back");
            Assert.That(((IIntegrator)StableIntegrator.RungeKutta4).Step(model, state, k1, 1.0 / 240).Position, Is.EqualTo(raw.Position));
            Assert.That(((IIntegrator)StableIntegrator.RungeKutta4).Name, Is.EqualTo("stable-rk4"));
        }

        [Test]
        public void CheapBound_NeverSaysBelowWhereTheRateIsNot_AndSkipsTheLawsInTheCommonCase()
        {
            // StableStepping skips the law evaluations where StiffnessSurelyBelow holds; that must imply the exact rate is
            // below the same limit (else a step that needs substeps would be taken whole). Models with every bounded law
            // kind (constant, Stepanek, exponential decay, none), wind, states from crawling to 1e5 m/s, steps 1e-5 to 1 s.
            var random = new Random(11);
            var models = new[]
            {
                Tennis(),
                FlightModel.Thesis(Ball.Tennis, new Air(1.21, new Vector3d(4, -1, 0)), Gravity.ZUp),
                new FlightModel(new Ball(0.0027, 0.02, Ball.ThinShellInertiaFactor), new Air(1.2).WithLogarithmicWind(new Vector3d(6, 0, 0)),
                    Gravity.ZUp, new ConstantDrag(0.5), StepanekLift.Instance, new ExponentialSpinDecay(2)),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance),
                new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp, null, null, new ExponentialSpinDecay(0.5)),
            };
            int below = 0, cases = 0;
            foreach (FlightModel model in models)
            {
                for (int i = 0; i < 4000; i++)
                {
                    double speed = Math.Pow(10, -2 + 7 * random.NextDouble());
                    var velocity = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * speed;
                    var spin = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * (3000 * random.NextDouble());
                    var state = new FlightState(new Vector3d(0, 0, 30 * random.NextDouble()), velocity, spin);
                    double step = Math.Pow(10, -5 + 5 * random.NextDouble());
                    double limit = 0.5 * random.NextDouble();
                    cases++;
                    if (model.StiffnessSurelyBelow(state, step, limit))
                    {
                        below++;
                        Assert.That(step * model.StiffnessRate(state, step), Is.LessThanOrEqualTo(limit), $"{model} {state} h={step}");
                    }
                }
            }

            Assert.That(below, Is.GreaterThan(cases / 10), "the bound is useful: it holds in a good share of the cases");
            Assert.That(Tennis().StiffnessSurelyBelow(Drive(), 1.0 / 240, 0.5), Is.True, "a tennis drive at 1/240 s skips the laws");
            var user = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, new LinearSpinDrag(0.3, 0.1));
            Assert.That(user.StiffnessSurelyBelow(Drive(), 1.0 / 240, 0.5), Is.False, "a law without a known bound is always evaluated");
        }

        [Test]
        public void StiffnessRate_BoundsTheDragEigenvalue()
        {
            // Constant C_D, no lift: sigma = 2 k C_D s (s + g h) / s; at h -> 0 exactly the drag eigenvalue 2 k C_D s.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, new ConstantDrag(0.5));
            var state = new FlightState(default, new Vector3d(50, 0, 0), default);
            double sigma = StableStepping.StiffnessRate(model, state, 1e-9);
            double expected = 1.1 * 2 * model.AerodynamicFactor * 0.5 * 50;
            // 1e-6 relative: the h = 1e-9 s speed-growth term g h / s = 2e-10, plus rounding (1.1: the one-sided margin
            // the criterion takes when the speed changes by less than 10 % within the step).
            Assert.That(sigma, Is.EqualTo(expected).Within(1e-6).Percent);
            Assert.That(StableStepping.StiffnessRate(FlightModel.Vacuum(Ball.Tennis, Gravity.ZUp), state, 0.1), Is.EqualTo(0));
        }

        [Test]
        public void SubstepCount_FollowsTheCriterion()
        {
            var model = new FlightModel(new Ball(0.12, 0.25), Air.SeaLevel, Gravity.ZUp, new ConstantDrag(0.47));
            var state = new FlightState(default, new Vector3d(100, 0, 0), default);
            StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
            double sigma = StableStepping.StiffnessRate(model, state, 0.25);
            Assert.That(StableStepping.SubstepCount(model, state, 0.25), Is.EqualTo((int)Math.Ceiling(0.25 * sigma)));
            Assert.That(StableStepping.SubstepCount(model, state, 0.25, 0.5), Is.EqualTo((int)Math.Ceiling(0.25 * sigma / 0.5)));
            StableStepping.Step(RungeKutta4.Instance, model, state, k1, 0.25, out _, out int taken);
            Assert.That(taken, Is.LessThanOrEqualTo(StableStepping.SubstepCount(model, state, 0.25)), "re-judged as the ball slows");
        }

        [Test]
        public void AtRestRelativeToTheAir_JudgesTheDragAtTheSpeedGravityGives()
        {
            var model = new FlightModel(new Ball(0.12, 0.25), Air.SeaLevel, Gravity.ZUp, new ConstantDrag(0.47));
            var state = new FlightState(new Vector3d(0, 0, 100), default, default);
            double sigma = StableStepping.StiffnessRate(model, state, 1.0);
            double expected = 2 * model.AerodynamicFactor * 0.47 * Gravity.Standard;
            // 1e-9 relative: 2 k C_D s_max with s_max = g h exactly, up to rounding.
            Assert.That(sigma, Is.EqualTo(expected).Within(1e-9).Percent);
        }

        [Test]
        public void Stepping_AllocatesNothing()
        {
            FlightModel model = Tennis();
            FlightState state = default;
            Action steps = () =>
            {
                state = Drive(); // the same start every run
                StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                for (int i = 0; i < 1000; i++)
                {
                    state = StableStepping.Step(RungeKutta4.Instance, model, state, k1, 1.0 / 60, out k1, out _);
                }
            };
            Assert.That(Allocation.SteadyStateBytes(steps), Is.EqualTo(0));
            Assert.That(state.IsFinite, Is.True);
        }

        [Test]
        public void BadInput_ThrowsNamingTheParameter()
        {
            FlightModel model = Tennis();
            FlightState state = Drive();
            StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
            Assert.That(() => StableStepping.Step(null!, model, state, k1, 0.01, out _, out _), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("integrator"));
            Assert.That(() => StableStepping.Step(RungeKutta4.Instance, null!, state, k1, 0.01, out _, out _), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("model"));
            Assert.That(() => StableStepping.Step(RungeKutta4.Instance, model, state, k1, -0.01, out _, out _), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("step"));
            Assert.That(() => StableStepping.Step(RungeKutta4.Instance, model, state, k1, 0.01, out _, out _, 3), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("stiffnessLimit"));
            Assert.That(() => StableStepping.SubstepCount(model, state, 0.01, 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("stiffnessLimit"));
            Assert.That(() => StableStepping.StiffnessRate(model, new FlightState(state.Position, new Vector3d(double.NaN, 0, 0), default), 0.01), Throws.InstanceOf<ArgumentException>().With.Property("ParamName").EqualTo("state"));
            Assert.That(() => new StableIntegrator(null!), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("inner"));
            Assert.That(() => new StableIntegrator(Heun.Instance, double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("stiffnessLimit"));
        }
    }
}
