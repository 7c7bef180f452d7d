using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Batch;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;
using NUnit.Framework;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Tests.Robustness
{
    /// <summary>
    /// Issue 15: the physics layer never gives NaN for finite input, and gives the true value wherever it fits in a
    /// double (lengths scaled before squaring). Values beyond double.MaxValue are infinite, never NaN.
    /// </summary>
    [TestFixture]
    public class OverflowTests
    {
        private static bool NoNaN(in StateDerivative d) =>
            !double.IsNaN(d.Acceleration.X) && !double.IsNaN(d.Acceleration.Y) && !double.IsNaN(d.Acceleration.Z) &&
            !double.IsNaN(d.AngularAcceleration.X) && !double.IsNaN(d.AngularAcceleration.Y) && !double.IsNaN(d.AngularAcceleration.Z);

        [Test]
        public void LiftAtSubnormalSpin_IsZero_AndTheStepFinite()
        {
            // A constant C_L (the thesis model) formed 1/|w|, which overflows below 1/double.MaxValue = 5.6e-309 rad/s: the kernel's
            // derivative was (NaN, -inf, inf) and the RK4 step not finite. At or below FlightModel.MinimumLiftSpinRate the
            // lift is zero in the general formula, the kernel and the batch alike, so such a spin flies as no spin.
            Assert.That(FlightModel.MinimumLiftSpinRate, Is.EqualTo(1e-150));
            var model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var spinless = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), default);
            StateDerivative k0 = model.Derivative(spinless);
            FlightState expected = ((IIntegrator)MagnusBall.Integration.RungeKutta4.Instance).Step(model, spinless, k0, 1.0 / 240, out StateDerivative expectedEnd, out _);
            foreach (Vector3d spin in new[] { new Vector3d(1e-310, 0, 0), new Vector3d(5e-324, 0, 0), new Vector3d(0, -1e-200, 3e-160), new Vector3d(1e-150, 0, 0) })
            {
                var state = new FlightState(spinless.Position, spinless.Velocity, spin);
                StateDerivative kernel = FlightKernel.Of(model).Derivative(state);
                Assert.That(kernel.Acceleration, Is.EqualTo(k0.Acceleration), $"kernel derivative at w = {spin}");
                Assert.That(model.GeneralDerivative(state).Acceleration, Is.EqualTo(k0.Acceleration), $"general formula at w = {spin}");
                FlightState next = ((IIntegrator)MagnusBall.Integration.RungeKutta4.Instance).Step(model, state, model.Derivative(state), 1.0 / 240, out StateDerivative end, out _);
                Assert.That(next.Position, Is.EqualTo(expected.Position), $"RK4 at w = {spin}");
                Assert.That(next.Velocity, Is.EqualTo(expected.Velocity), $"RK4 at w = {spin}");
                Assert.That(end.Acceleration, Is.EqualTo(expectedEnd.Acceleration), $"RK4's end rates at w = {spin}");

                var batch = new BallBatch(model, 1);
                batch.Add(state);
                batch.Advance(1.0 / 240);
                Assert.That(batch.GetState(0).Velocity, Is.EqualTo(expected.Velocity), $"batch at w = {spin}");
            }

            // Just above the cut-off the lift is the constant C_L's full force again (the thesis model's own behaviour).
            var above = new FlightState(spinless.Position, spinless.Velocity, new Vector3d(0, 2e-150, 0));
            Assert.That(model.Derivative(above).Acceleration.X, Is.Not.EqualTo(k0.Acceleration.X));
            Assert.That(model.Derivative(above).Acceleration.IsFinite, Is.True);
        }

        [Test]
        public void LiftAtSubnormalSpin_EveryIntegratorAndDriver_FliesAsNoSpin()
        {
            // The same cut-off through every other way a step is taken: DP54's fixed step (the kernel's stages; before the
            // cut-off its NaN check sent the step to the general stages, whose scaled fallback gave the constant C_L's full
            // lift), DP54's adaptive steps, Heun (the kernel's own Heun, NaN before), a FlightStepper and a
            // TrajectoryPredictor end to end (refused at the first step before). A spin at or below the cut-off must give
            // the spinless flight's very numbers: with no spin decay the spin is carried unchanged and read by nothing else.
            var model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var spinless = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), default);
            const double h = 1.0 / 240;
            foreach (Vector3d spin in new[] { new Vector3d(1e-310, 0, 0), new Vector3d(5e-324, -5e-324, 0), new Vector3d(0, 7e-151, -7e-151) })
            {
                var state = new FlightState(spinless.Position, spinless.Velocity, spin);
                foreach (IIntegrator method in new IIntegrator[] { DormandPrince54.Instance, Heun.Instance })
                {
                    FlightState expected = method.Step(model, spinless, model.Derivative(spinless), h, out StateDerivative expectedEnd, out _);
                    FlightState next = method.Step(model, state, model.Derivative(state), h, out StateDerivative end, out _);
                    Assert.That(next.Velocity, Is.EqualTo(expected.Velocity), $"{method} at w = {spin}");
                    Assert.That(next.Position, Is.EqualTo(expected.Position), $"{method} at w = {spin}");
                    Assert.That(end.Acceleration, Is.EqualTo(expectedEnd.Acceleration), $"{method}'s end rates at w = {spin}");
                }

                var reference = new FlightStepper(model, DormandPrince54.Instance);
                var adaptive = new FlightStepper(model, DormandPrince54.Instance);
                reference.Reset(spinless);
                adaptive.Reset(state);
                for (int i = 0; i < 20; i++)
                {
                    Assert.That(reference.TryStepAdaptive(DormandPrince54.Instance, 0.05), Is.EqualTo(StepOutcome.Taken));
                    Assert.That(adaptive.TryStepAdaptive(DormandPrince54.Instance, 0.05), Is.EqualTo(StepOutcome.Taken), $"adaptive step {i} at w = {spin}");
                    Assert.That(adaptive.State.Velocity, Is.EqualTo(reference.State.Velocity), $"adaptive step {i} at w = {spin}");
                    Assert.That(adaptive.State.Time, Is.EqualTo(reference.State.Time), $"adaptive step {i} at w = {spin}");
                }

                var events = new FlightEventSet(model.Up, Plane.Ground(model));
                var expectedRun = new TrajectoryPredictor(model, RungeKutta4.Instance, h, events).Predict(spinless, 5, Span<Vector3d>.Empty);
                Prediction run = new TrajectoryPredictor(model, RungeKutta4.Instance, h, events).Predict(state, 5, Span<Vector3d>.Empty);
                Assert.That(expectedRun.Stopped, Is.True, "the spinless serve lands within 5 s");
                Assert.That(run.Diverged, Is.False, $"predictor at w = {spin}");
                Assert.That(run.Stopped, Is.True, $"predictor at w = {spin}");
                Assert.That(run.EndState.Position, Is.EqualTo(expectedRun.EndState.Position), $"predictor's landing at w = {spin}");
                Assert.That(run.Steps, Is.EqualTo(expectedRun.Steps), $"predictor at w = {spin}");
            }
        }

        [Test]
        public void ConstantLift_WithSpinDecayingThroughTheCutOff_FliesOnFinite()
        {
            // A constant C_L with exponential spin decay (tau = 5 ms, well inside RK4's stability limit at 1/240 s): the spin
            // falls from 100 rad/s through the cut-off (after tau ln(1e152) = 1.75 s) and on through the subnormals (below
            // about 5e-309 rad/s after 3.5 s, where 1/|w| overflows) to 0. Every RK4 step, every adaptive DP54 step and the
            // batch must go on finite; before the cut-off the RK4 step went non-finite once the spin was subnormal.
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Vector3d.Zero).WithSpinDecay(new ExponentialSpinDecay(0.005));
            var start = new FlightState(Vector3d.Zero, new Vector3d(30, 1, 5), new Vector3d(0, 100, 20));
            var rk4 = new FlightStepper(model, RungeKutta4.Instance);
            rk4.Reset(start);
            var batch = new BallBatch(model, 1, new Plane(new Vector3d(0, 0, -1e6), Vector3d.UnitZ));
            batch.Add(start);
            bool crossed = false, subnormal = false;
            for (int i = 0; i < 5 * 240; i++)
            {
                Assert.That(rk4.TryStep(1.0 / 240), Is.EqualTo(StepOutcome.Taken), $"RK4 step {i}, w = {rk4.State.AngularVelocity}");
                double rate = rk4.State.AngularVelocity.Length;
                crossed |= rate > 0 && rate <= FlightModel.MinimumLiftSpinRate;
                subnormal |= rate > 0 && rate < 2.2250738585072014e-308;
            }

            batch.Advance(1.0 / 240, 5 * 240);
            Assert.That(crossed && subnormal, Is.True, "the spin passed the cut-off and the subnormals");
            Assert.That(rk4.State.IsFinite, Is.True);
            Assert.That(batch.HasDiverged(0), Is.False);
            Assert.That(batch.GetState(0).Velocity, Is.EqualTo(rk4.State.Velocity), "the batch is the single-ball path");

            var dp = new FlightStepper(model, DormandPrince54.Instance);
            dp.Reset(start);
            // 5 s at most 0.05 s a step is 100 steps; the lift's jump at the cut-off costs a few rejections inside a step.
            for (int i = 0; i < 1000 && dp.State.Time < 5; i++)
            {
                Assert.That(dp.TryStepAdaptive(DormandPrince54.Instance, 0.05), Is.EqualTo(StepOutcome.Taken), $"DP54 step {i}, w = {dp.State.AngularVelocity}");
            }

            Assert.That(dp.State.Time, Is.GreaterThanOrEqualTo(5));
            Assert.That(dp.State.IsFinite, Is.True);
            Assert.That(dp.State.AngularVelocity.Length, Is.LessThanOrEqualTo(FlightModel.MinimumLiftSpinRate));
        }

        [Test]
        public void LiftLawsThatDoNotVanishAtZeroSpin_AreCutOffToo_AndTheOthersLoseNothing()
        {
            // A PiecewiseLinearLift whose first C_L is not 0 holds it for every S below its first point, as a constant C_L
            // does: at a subnormal spin its kernel lift divided by |w| (s^2 / |w| overflowed: NaN, and a non-finite RK4 step
            // before the cut-off). Stepanek's lift, C_L = S / (2.022 S + 0.981) -> 0, gives at 2e-150 rad/s (just above the
            // cut-off) a lift of about k s r |w| = 1e-153 m/s^2: nothing at the acceleration's resolution (ulp(17) = 3.6e-15).
            var state = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(1e-310, 0, 0));
            var spinless = new FlightState(state.Position, state.Velocity, default);
            var table = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, ConstantDrag.ThesisTennis,
                new PiecewiseLinearLift(new[] { 0.0, 0.2 }, new[] { 0.15, 0.3 }));
            var stepanek = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
            foreach (FlightModel model in new[] { table, stepanek })
            {
                StateDerivative k0 = model.Derivative(spinless);
                FlightState expected = ((IIntegrator)RungeKutta4.Instance).Step(model, spinless, k0, 1.0 / 240, out _, out _);
                Assert.That(FlightKernel.Of(model).Derivative(state).Acceleration, Is.EqualTo(k0.Acceleration), $"{model.Lift} kernel");
                Assert.That(model.GeneralDerivative(state).Acceleration, Is.EqualTo(k0.Acceleration), $"{model.Lift} general formula");
                FlightState next = ((IIntegrator)RungeKutta4.Instance).Step(model, state, model.Derivative(state), 1.0 / 240, out _, out _);
                Assert.That(next.Velocity, Is.EqualTo(expected.Velocity), $"{model.Lift} RK4");
            }

            var above = new FlightState(state.Position, state.Velocity, new Vector3d(0, 2e-150, 0));
            Assert.That(stepanek.Derivative(above).Acceleration, Is.EqualTo(stepanek.Derivative(spinless).Acceleration), "Stepanek just above the cut-off");
            Assert.That(table.Derivative(above).Acceleration.X, Is.Not.EqualTo(table.Derivative(spinless).Acceleration.X), "the table's C_L 0.15 just above");
        }

        [Test]
        public void Length_ScalesBeforeSquaring()
        {
            Assert.That(new Vector3d(1e155, 0, 0).Length, Is.EqualTo(1e155));
            Assert.That(new Vector3d(3e200, 4e200, 0).Length, Is.EqualTo(5e200).Within(1e185)); // 1 ulp-scale: sqrt of scaled components
            Assert.That(new Vector3d(1e-160, 0, 0).Length, Is.EqualTo(1e-160));
            Assert.That(new Vector3d(0, -5e-324, 0).Length, Is.EqualTo(5e-324));
            Assert.That(new Vector3d(3, 4, 0).Length, Is.EqualTo(5), "the everyday path is the plain formula");
            Assert.That(new Vector3d(double.MaxValue, double.MaxValue, 0).Length, Is.EqualTo(double.PositiveInfinity), "the true length exceeds double.MaxValue");
            Assert.That(double.IsNaN(new Vector3d(double.NaN, 0, 0).Length), Is.True);
        }

        [TestCase(1e308, 0, 0)]
        [TestCase(-1.7e308, 1.7e308, 1e300)]
        [TestCase(1e-300, 0, 0)]
        [TestCase(0, 5e-324, -5e-324)]
        public void NormalizedOrZero_IsAUnitVectorForEveryNonZeroFiniteVector(double x, double y, double z)
        {
            Vector3d n = new Vector3d(x, y, z).NormalizedOrZero();
            Assert.That(n.Length, Is.EqualTo(1).Within(4e-16));
            Assert.That(Math.Sign(n.X), Is.EqualTo(Math.Sign(x)));
        }

        [Test]
        public void Derivative_AtAHugeFiniteVelocity_IsTheTrueDrag()
        {
            // A 1 kg ball (k = 1.225 pi 0.1^2 / 2 = 0.0192 /m), C_D 0.5, at 1e150 m/s: k C_D s^2 = 9.6e297, which fits.
            // |v|^2 = 1e300 fits too, but s^2 for the Magnus term and w x v at 1e150 m/s x 1e160 rad/s do not.
            var model = new FlightModel(new Ball(1, 0.1), Air.SeaLevel, Gravity.ZUp, new ConstantDrag(0.5), new ConstantLift(0.2));
            double k = model.AerodynamicFactor;
            var state = new FlightState(Vector3d.Zero, new Vector3d(1e150, 0, 0), new Vector3d(0, 1e160, 0));
            StateDerivative d = model.Derivative(state);
            Assert.That(d.Acceleration.IsFinite, Is.True, d.ToString());
            // Drag along -x, lift along w x v = (0, 1, 0) x (1, 0, 0) = -z: the exact values to rounding (a few ulps).
            Assert.That(d.Acceleration.X, Is.EqualTo(-k * 0.5 * 1e300).Within(1e-14 * k * 1e300));
            Assert.That(d.Acceleration.Z, Is.EqualTo(-k * 0.2 * 1e300).Within(1e-14 * k * 1e300));
        }

        [Test]
        public void Derivative_OfTheIssuesState_IsNeverNaN_AndDivergesAsInfinity()
        {
            // The issue's v = (1e155, 0, 0) with a tennis ball: k C_D s^2 = 0.0363 x 0.55 x 1e310 = 2.0e308 > double.MaxValue.
            var model = FlightModel.Thesis(new Ball(0.057, 0.033), new Air(1.21), Gravity.ZUp);
            StateDerivative d = model.Derivative(new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e155, 0, 0), new Vector3d(0, 125.7, 0)));
            Assert.That(NoNaN(d), Is.True, d.ToString());
            Assert.That(d.Acceleration.X, Is.EqualTo(double.NegativeInfinity), "drag beyond double.MaxValue");
            Assert.That(d.Acceleration.Y, Is.EqualTo(0), "no force across: 0, not 0 x infinity");
        }

        [Test]
        public void Derivative_AtOrdinaryStates_IsBitForBitThePlainFormula()
        {
            // The scaled path runs only when the plain one overflows: a drive gives the formula's value. The thesis model's
            // kernel folds its constant lift (no 1/s), so it matches the formula to rounding (2e-15 relative), not bit for bit.
            var model = FlightModel.Thesis(new Ball(0.057, 0.033), new Air(1.21), Gravity.ZUp);
            var v = new Vector3d(29.7, 0, 4.2);
            var w = new Vector3d(0, 125.7, 0);
            StateDerivative d = model.Derivative(new FlightState(Vector3d.Zero, v, w));
            double s = v.Length;
            Vector3d expected = Gravity.ZUp + v * (-model.AerodynamicFactor * 0.55 * s) +
                                Vector3d.Cross(w, v / s) * (model.AerodynamicFactor * 0.175 * s * s / w.Length);
            Assert.That(Vector3d.Distance(d.Acceleration, expected), Is.LessThanOrEqualTo(2e-15 * expected.Length));
            // A model whose kernel does not fold (Stepanek's drag with a linear lift) gives the general formula bit for bit;
            // Stepanek's lift folds (with Stepanek's drag beside it: FlightKernel's TryFoldedRates), to rounding: within
            // 1e-15 of |g| + k s^2 (C_D + C_L), the bound FlightKernelTests asserts for the fold.
            var state = new FlightState(Vector3d.Zero, v, w);
            var linear = new FlightModel(Ball.Tennis, Shots.CrossAir, Gravity.ZUp, StepanekDrag.Instance, new LinearSpinLift(0.6));
            Assert.That(linear.Derivative(state).Acceleration, Is.EqualTo(linear.GeneralDerivative(state).Acceleration));
            FlightModel stepanek = Shots.StepanekTennis(Gravity.ZUp);
            double scale = 9.81 + stepanek.AerodynamicFactor * v.LengthSquared * (0.8 + 0.5);
            Assert.That(Vector3d.Distance(stepanek.Derivative(state).Acceleration, stepanek.GeneralDerivative(state).Acceleration), Is.LessThanOrEqualTo(1e-15 * scale));
        }

        [Test]
        public void SpinDecay_WithATinyTimeConstant_IsNeverNaN()
        {
            var decay = new ExponentialSpinDecay(1e-320); // 1/tau overflows
            Vector3d a = decay.SpinAcceleration(new Vector3d(0, 1e-20, -1), default);
            Assert.That(a.X, Is.EqualTo(0), "0, not 0 x infinity");
            Assert.That(a.Y, Is.EqualTo(-1e-20 / 1e-320), "fits: -1e300");
            Assert.That(a.Z, Is.EqualTo(double.PositiveInfinity), "1e320 does not fit");
        }

        [Test]
        public void AeroConditions_AtATinySpeed_AreNeverNaN()
        {
            var zeroSpin = new AeroConditions(1e-310, 0, 0, 0.033, 1.2, 1.8e-5);
            Assert.That(zeroSpin.SpinParameter, Is.EqualTo(0), "0 spin is 0, not 0 x infinity");
            var spinning = new AeroConditions(1e-300, 1e-10, 1e-10, 0.033, 1.2, 1.8e-5);
            Assert.That(spinning.SpinParameter, Is.EqualTo(1e-10 / 1e-300 * 0.033).Within(1e277));
            var fast = new AeroConditions(1e306, 0, 0, 0.033, 1e3, 1e-10);
            Assert.That(fast.ReynoldsNumber, Is.EqualTo(double.PositiveInfinity), "beyond double.MaxValue");
            var slowAir = new AeroConditions(1e306, 0, 0, 1e-10, 1e-3, 1e3);
            Assert.That(slowAir.ReynoldsNumber, Is.EqualTo(1e-3 / 1e3 * 1e306 * 2e-10).Within(1e287), "fits: no intermediate overflow");
        }

        [Test]
        public void LiftLaws_AtHugeSpinParameters_KeepTheirLimits()
        {
            var huge = new AeroConditions(1, double.MaxValue, double.MaxValue, 1, 1, 1);
            Assert.That(StepanekLift.Instance.LiftCoefficient(huge), Is.EqualTo(1 / 2.022).Within(1e-15));
            Assert.That(NathanBaseballLift.Instance.LiftCoefficient(huge), Is.EqualTo(1.120 / 2.333).Within(1e-15));
            var table = new PiecewiseLinearLift(new[] { 0.0, 1.0 }, new[] { -1.5e308, 1.5e308 });
            Assert.That(table.Evaluate(0.5), Is.EqualTo(0).Within(1e293), "halfway between opposite extremes, not infinity");
            Assert.That(new LinearSpinLift(0).LiftCoefficient(huge), Is.EqualTo(0));
            Assert.That(new LinearSpinDrag(0.2, 0).DragCoefficient(new AeroConditions(1e-320, 1, 1, 1, 1, 1)), Is.EqualTo(0.2));
        }

        [Test]
        public void Spin_Toward_AcceptsTinyAndHugeVectors()
        {
            Vector3d w = Spin.Toward(new Vector3d(1e-300, 0, 0), new Vector3d(0, 0, 1e308), 10);
            Assert.That(w.Length, Is.EqualTo(10).Within(1e-14));
        }

        [Test]
        public void Energies_AreNeverNaN()
        {
            var model = FlightModel.Vacuum(new Ball(1, 0.1), new Vector3d(0, 0, -1e308));
            var state = new FlightState(new Vector3d(0, 0, -1e308), new Vector3d(1e200, 0, 0), new Vector3d(1e200, 0, 0));
            Assert.That(double.IsNaN(model.MechanicalEnergy(state)), Is.False);
            Assert.That(double.IsNaN(model.RotationalEnergy(state)), Is.False);
            var small = new FlightState(new Vector3d(0, 0, 1), new Vector3d(3, 0, 4), Vector3d.Zero);
            Assert.That(FlightModel.Vacuum(new Ball(2, 0.1), Gravity.ZUp).MechanicalEnergy(small), Is.EqualTo(2 * (12.5 + 9.80665)));
        }
    }
}
