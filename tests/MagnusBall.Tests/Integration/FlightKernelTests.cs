using System;
using System.Linq;
using System.Collections.Generic;
using MagnusBall.Aerodynamics;
using MagnusBall.Flight;
using MagnusBall.Integration;
using NUnit.Framework;

using MagnusBall.Integration.Kernels;

namespace MagnusBall.Tests.Integration
{
    /// <summary>
    /// The flight kernel (FlightModel's struct-specialised derivative and RK4/Heun steps) against the general formula with
    /// every law called through its interface: equal bit for bit, for every built-in law, a user's own laws, wind
    /// (uniform and a profile), a vacuum and air without aerodynamic laws.
    /// </summary>
    [TestFixture]
    public class FlightKernelTests
    {
        /// <summary>A user's own drag law (not a built-in type): counts its calls.</summary>
        private sealed class CountingDrag : IDragModel
        {
            public int Calls;

            public double DragCoefficient(in AeroConditions conditions)
            {
                Calls++;
                return 0.4 + 1e-7 * conditions.ReynoldsNumber + 0.1 * conditions.SpinParameter;
            }
        }

        private sealed class UserLift : ILiftModel
        {
            public double LiftCoefficient(in AeroConditions conditions) => 0.3 * Math.Tanh(conditions.TransverseSpinParameter * 3);
        }

        private sealed class UserDecay : ISpinDecayModel
        {
            public Vector3d SpinAcceleration(in Vector3d angularVelocity, in AeroConditions conditions) =>
                angularVelocity * (-0.01 * conditions.Speed - 1e-3 * conditions.SpinRate);
        }

        public static IEnumerable<TestCaseData> Models()
        {
            var air = new Air(1.21);
            var windy = new Air(1.1, new Vector3d(3, -2, 0.5));
            var profile = new Air(1.2).WithLogarithmicWind(new Vector3d(6, 1, 0));
            Vector3d g = Gravity.ZUp;
            yield return new TestCaseData(FlightModel.Thesis(Ball.Tennis, air, g), "ConstantDragLaw, ConstantLiftLaw, NoSpinDecay").SetName("Thesis");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, windy, g, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                "StepanekDragLaw, StepanekLiftLaw, ExponentialSpinDecayLaw").SetName("FullTennisWindy");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, air, g, StepanekDrag.Instance), "StepanekDragLaw, NoLift, NoSpinDecay").SetName("DragOnly");
            yield return new TestCaseData(FlightModel.Vacuum(Ball.Tennis, g), "NoDrag, NoLift, NoSpinDecay").SetName("Vacuum");
            yield return new TestCaseData(
                new FlightModel(new Ball(0.04593, 0.021335, 0.4), profile, g, LinearSpinDrag.GolfSmitsSmith, PiecewiseLinearLift.GolfSmitsSmith, new ExponentialSpinDecay(25)),
                "LinearSpinDragLaw, PiecewiseLinearLiftLaw, ExponentialSpinDecayLaw").SetName("GolfWindProfile");
            yield return new TestCaseData(
                new FlightModel(new Ball(0.145, 0.0366, 0.4), windy, g, NathanBaseballDrag.Instance, NathanBaseballLift.Instance, SpeedProportionalSpinDecay.BaseballNathan),
                "NathanBaseballDragLaw, NathanBaseballLiftLaw, SpeedProportionalSpinDecayLaw").SetName("Baseball");
            yield return new TestCaseData(
                new FlightModel(Ball.Soccer, air, g, GoffCarreSoccerDrag.Instance, PiecewiseLinearLift.SoccerGoffCarre),
                "GoffCarreSoccerDragLaw, PiecewiseLinearLiftLaw, NoSpinDecay").SetName("Soccer");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, windy, g, ConstantDrag.CrossLindseyTennis, LinearSpinLift.Cross2020Tennis),
                "ConstantDragLaw, LinearSpinLiftLaw, NoSpinDecay").SetName("CrossLinearLift");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, profile, g, new CountingDrag(), new UserLift(), new UserDecay()),
                "InterfaceDrag, InterfaceLift, InterfaceSpinDecay").SetName("UserLaws");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, Air.Vacuum, g, StepanekDrag.Instance, StepanekLift.Instance, SpeedProportionalSpinDecay.TennisCrossLindsey),
                "NoDrag, NoLift, SpeedProportionalSpinDecayLaw").SetName("VacuumWithSpinDecay");
            // Gravity.Along gives -0 components ((0, 1, 0) * -9.80665): the kernel must leave them as they are.
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.Along(new Vector3d(0, 1, 0)), StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                "NoDrag, NoLift, ExponentialSpinDecayLaw").SetName("VacuumWithSpinDecayNegativeZeros");
            // Constant drag without lift reads nothing (the folded kernel) but is the general formula bit for bit.
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, windy, g, ConstantDrag.CrossLindseyTennis), "ConstantDragLaw, NoLift, NoSpinDecay").SetName("ConstantDragOnly");
            yield return new TestCaseData(
                new FlightModel(Ball.Tennis, air, Gravity.Along(new Vector3d(0, 1, 0)), ConstantDrag.CrossLindseyTennis, null, new ExponentialSpinDecay(3)),
                "ConstantDragLaw, NoLift, ExponentialSpinDecayLaw").SetName("ConstantDragWithSpinDecay");
        }

        // States across the reachable range: fast and slow, spin along and across the flight, no spin, still (below the
        // aerodynamic cut-off speed), negative heights (under a profile's ground), huge spin parameters.
        private static IEnumerable<FlightState> States()
        {
            var random = new Random(7);
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 0, 0), new Vector3d(300, 0, 0)); // gyro spin
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), default);                   // no spin
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e-160, 0, 0), new Vector3d(0, 50, 0)); // below the cut-off
            yield return new FlightState(new Vector3d(0, 0, -2), new Vector3d(0.01, 0, 0), new Vector3d(0, 5000, 0)); // S ~ 1e4
            for (int i = 0; i < 200; i++)
            {
                double speed = Math.Pow(10, -3 + 5 * random.NextDouble());
                var velocity = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * speed;
                var spin = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * (600 * random.NextDouble());
                var position = new Vector3d(50 * random.NextDouble(), 10 * random.NextDouble(), 30 * random.NextDouble() - 1);
                yield return new FlightState(position, velocity, spin, random.NextDouble());
            }
        }

        [TestCaseSource(nameof(Models))]
        public void Kernel_IsPickedForTheLaws(FlightModel model, string laws)
        {
            Assert.That(FlightKernel.Of(model).ToString(), Is.EqualTo($"FlightKernel<{laws}>"));
        }

        [TestCaseSource(nameof(Models))]
        public void Derivative_EqualsTheGeneralFormula_BitForBit(FlightModel model, string laws)
        {
            bool folded = Folded(laws);
            foreach (FlightState state in States())
            {
                StateDerivative fast = FlightKernel.DerivativeOf(model, state);
                StateDerivative general = model.GeneralDerivative(state);
                AssertSame(fast.Velocity, general.Velocity, state);
                if (folded)
                {
                    // The folded forms: to rounding, within 1e-15 (about 4.5 ulp) of the largest terms (see the two tests
                    // below; ConformanceTests holds every law and form to its bound in ulp).
                    Assert.That((fast.Acceleration - general.Acceleration).Length, Is.LessThanOrEqualTo(1e-15 * Rounding.ForceScale(model, state)), $"{state}");
                }
                else
                {
                    AssertSame(fast.Acceleration, general.Acceleration, state);
                }

                AssertSame(fast.AngularAcceleration, general.AngularAcceleration, state);
            }
        }

        // A lift law that reads no spin parameter (constant C_L) runs through the folded form (C_L s / |w|) (w x v_rel), and
        // Stepanek's lift through its own (FlightKernel.StepanekLiftFold, with Stepanek's drag folded beside it).
        private static bool Folded(string laws) => laws.Contains("ConstantLiftLaw") || laws.Contains("StepanekLiftLaw");

        [Test]
        public void FoldedDerivative_EqualsTheGeneralFormula_ToRounding()
        {
            // The folded lift differs from the general formula only in rounding: a handful of roundings of terms no larger
            // than gravity + drag + lift, so within 1e-15 (about 4.5 ulp) of that sum, component by component.
            foreach (FlightModel model in new[]
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21, new Vector3d(3, -2, 0.5)), Gravity.ZUp),
                new FlightModel(Ball.Tennis, new Air(1.2).WithLogarithmicWind(new Vector3d(6, 1, 0)), Gravity.ZUp,
                    ConstantDrag.CrossLindseyTennis, new ConstantLift(-0.3), new ExponentialSpinDecay(3)),
            })
            {
                foreach (FlightState state in States())
                {
                    StateDerivative fast = FlightKernel.DerivativeOf(model, state);
                    StateDerivative general = model.GeneralDerivative(state);
                    double speed = (state.Velocity - model.Air.WindAt(state.Position, model.Up)).Length;
                    double drag = ((ConstantDrag)model.Drag!).Value, lift = Math.Abs(((ConstantLift)model.Lift!).Value);
                    double scale = model.Gravity.Length + model.AerodynamicFactor * speed * speed * (drag + lift);
                    Assert.That((fast.Acceleration - general.Acceleration).Length, Is.LessThanOrEqualTo(1e-15 * scale), $"{state}");
                    AssertSame(fast.AngularAcceleration, general.AngularAcceleration, state);
                }
            }
        }

        private static IEnumerable<FlightModel> StepanekLiftModels()
        {
            var windy = new Air(1.1, new Vector3d(3, -2, 0.5));
            yield return new FlightModel(Ball.Tennis, windy, Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            yield return new FlightModel(Ball.Tennis, new Air(1.21), Gravity.YUp, StepanekDrag.Instance, StepanekLift.Instance);
            yield return new FlightModel(Ball.Tennis, windy, Gravity.ZUp, ConstantDrag.CrossLindseyTennis, StepanekLift.Instance, SpeedProportionalSpinDecay.TennisCrossLindsey);
            yield return new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, null, StepanekLift.Instance);
            // A wind profile: the general formula throughout (the fold is for still air and a uniform wind).
            yield return new FlightModel(Ball.Tennis, new Air(1.2).WithLogarithmicWind(new Vector3d(6, 1, 0)), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance);
        }

        // States outside the range the Stepanek fold is taken in (FlightKernel.FoldMinimum and the rest), relative to the
        // model's air: the general formula there, bit for bit. The first two overflow within an RK4 step.
        private static IEnumerable<FlightState> StatesOutsideTheFold(FlightModel model)
        {
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(3e100, 1, 5), new Vector3d(10, 150, 20));   // s^2 past 1e200
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(1e60, 0, 0), new Vector3d(0, 1e45, 0));     // |w x v|^2 past 1e200
            Vector3d wind = model.Air.Wind;
            yield return new FlightState(new Vector3d(0, 0, 1), wind + new Vector3d(3e-101, 0, 1e-101), new Vector3d(10, 150, 20)); // s^2 below 1e-200
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1e-60, 0));      // |w| below 1e-50
            yield return new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 3e50, 1));       // |w| past 1e50
            yield return new FlightState(new Vector3d(0, 0, 1), wind + new Vector3d(30, 0, 0), new Vector3d(1, 1e-110, 0)); // |w x v|^2 = 9e-218: below 1e-200, not 0
        }

        [Test]
        public void FoldedStepanekLift_EqualsTheGeneralFormula_ToRounding()
        {
            // The fold differs from the general formula in rounding only: C_L from the sum of squares rather than the rounded
            // speed squared, w x v_rel rather than w x v_hat, the drag as (g + 0.508 e + G e) + lift with G read from z = Kappa s^2 /
            // (r |w|)^2 rather than through u = s / (r |w|), and one reciprocal of |w|. Each is a few
            // roundings of terms no larger than gravity + k s^2 (C_D + C_L) with C_D <= 0.7981 and C_L <= 0.4946 (the laws'
            // limits), so within 1e-15 (about 4.5 ulp) of that sum, in the length of the difference. The spin's rates are
            // untouched.
            double worst = 0;
            foreach (FlightModel model in StepanekLiftModels())
            {
                foreach (FlightState state in States())
                {
                    StateDerivative fast = FlightKernel.DerivativeOf(model, state);
                    StateDerivative general = model.GeneralDerivative(state);
                    double speed = (state.Velocity - model.Air.WindAt(state.Position, model.Up)).Length;
                    double scale = model.Gravity.Length + model.AerodynamicFactor * speed * speed * (0.7981 + 0.4946);
                    double difference = (fast.Acceleration - general.Acceleration).Length;
                    worst = Math.Max(worst, difference / scale);
                    Assert.That(difference, Is.LessThanOrEqualTo(1e-15 * scale), $"{model}: {state}");
                    AssertSame(fast.AngularAcceleration, general.AngularAcceleration, state);
                }

                foreach (FlightState state in StatesOutsideTheFold(model))
                {
                    StateDerivative fast = FlightKernel.DerivativeOf(model, state);
                    StateDerivative general = model.GeneralDerivative(state);
                    AssertSame(fast.Acceleration, general.Acceleration, state);
                    AssertSame(fast.AngularAcceleration, general.AngularAcceleration, state);
                }
            }

            TestContext.WriteLine($"worst difference {worst:E2} of |g| + k s^2 (C_D + C_L)");
        }

        [TestCaseSource(nameof(Models))]
        public void Rk4AndHeunSteps_EqualTheGeneralFormula_BitForBit(FlightModel model, string laws)
        {
            // Unfolded laws: the steps are the formulas on the general derivative, bit for bit. Folded laws: the formulas on the
            // kernel's own (folded) derivative, bit for bit.
            bool folded = Folded(laws);
            Func<FlightState, StateDerivative> spec = folded ? s => FlightKernel.DerivativeOf(model, s) : s => model.GeneralDerivative(s);
            foreach (FlightState state in States())
            {
                foreach (double step in new[] { 1.0 / 240, 0.03 })
                {
                    StateDerivative k1 = spec(state);
                    FlightState rk4 = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k1, step, out StateDerivative rk4End, out int rk4Evaluations);
                    FlightState heun = ((IIntegrator)Heun.Instance).Step(model, state, k1, step, out StateDerivative heunEnd, out int heunEvaluations);
                    FlightState rk4Reference = ReferenceRk4(model, state, k1, step, spec);
                    FlightState heunReference = ReferenceHeun(model, state, k1, step, spec);
                    AssertSame(rk4, rk4Reference, state);

                    AssertSame(heun, heunReference, state);
                    if (rk4.IsFinite && rk4Reference.IsFinite)
                    {
                        AssertSame(rk4End.Acceleration, spec(rk4).Acceleration, state);
                        AssertSame(rk4End.AngularAcceleration, spec(rk4).AngularAcceleration, state);
                    }

                    if (heunReference.IsFinite)
                    {
                        AssertSame(heunEnd.Acceleration, spec(heunReference).Acceleration, state);
                    }

                    Assert.That(rk4Evaluations, Is.EqualTo(4));
                    Assert.That(heunEvaluations, Is.EqualTo(2));
                }
            }
        }

        // The flight core takes plain RK4 and the stable RK4's one-substep case straight from the kernel, its end written into
        // the core's own fields (FlightStepper.TryStep): the same bits, end rates and evaluation counts as the integrators'
        // public Step, including stable steps that need substeps (0.5 and 3 s at the fast states) and steps that diverge.
        // Both stable branches are reached for every model with air (counted by the shortcut's own condition).
        [TestCaseSource(nameof(Models))]
        public void FlightCoreStep_EqualsTheIntegratorsStep_BitForBit(FlightModel model, string laws)
        {
            int substepped = 0, single = 0;
            foreach (IIntegrator integrator in new IIntegrator[] { RungeKutta4.Instance, StableIntegrator.RungeKutta4 })
            {
                var stepper = new FlightStepper(model, integrator);
                foreach (FlightState state in States())
                {
                    foreach (double step in new[] { 1.0 / 240, 0.03, 0.5, 3.0 })
                    {
                        StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                        FlightState expected = integrator.Step(model, state, k1, step, out StateDerivative expectedEnd, out int evaluations);
                        if (integrator is StableIntegrator stable)
                        {
                            // The condition the core's shortcut tests: 1 takes the kernel directly, more goes through Step.
                            if (StableStepping.SubstepsFor(model, state, step, stable.StiffnessLimit) > 1)
                            {
                                substepped++;
                            }
                            else
                            {
                                single++;
                            }
                        }

                        stepper.Reset(state);
                        long before = stepper.DerivativeEvaluations; // Reset's evaluation of the start derivative
                        StepOutcome outcome = stepper.TryStep(step);
                        bool finite = expected.IsFinite && expectedEnd.Acceleration.IsFinite && expectedEnd.AngularAcceleration.IsFinite;
                        Assert.That(outcome, Is.EqualTo(finite ? StepOutcome.Taken : StepOutcome.Diverged), $"{integrator.Name} from {state}, h {step}");
                        if (finite)
                        {
                            AssertSame(stepper.State, expected, state);
                            AssertSame(stepper.Derivative.Velocity, expectedEnd.Velocity, state);
                            AssertSame(stepper.Derivative.Acceleration, expectedEnd.Acceleration, state);
                            AssertSame(stepper.Derivative.AngularAcceleration, expectedEnd.AngularAcceleration, state);
                            Assert.That(stepper.DerivativeEvaluations - before, Is.EqualTo(evaluations));
                        }
                    }
                }
            }

            if (model.Air.Density > 0 && laws != "NoDrag, NoLift, NoSpinDecay")
            {
                Assert.That(substepped, Is.GreaterThan(0), "no stable step needed substeps: the test would not reach that branch");
            }

            Assert.That(single, Is.GreaterThan(0), "no stable step took the shortcut");
        }

        [TestCaseSource(nameof(Models))]
        public void Dp54Step_EqualsTheStepThroughDerivative_BitForBit(FlightModel model, string laws)
        {
            // Every model, folded ones too: the step through FlightModel.Derivative is DormandPrince54's arithmetic before the
            // kernel had the stages, and FlightModel.Derivative is the kernel's own derivative (where finite).
            var methods = new[] { DormandPrince54.Instance, new DormandPrince54(1e-8, 1e-8), new DormandPrince54(1e-3, 1e-5) };
            int compared = 0;
            foreach (FlightState state in States())
            {
                foreach (double step in new[] { 1.0 / 240, 0.03, 0.4 })
                {
                    StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                    foreach (DormandPrince54 method in methods)
                    {
                        bool accepted = method.TryStep(model, state, k1, step, out DormandPrince54Step fast);
                        bool reference = method.TryStepThroughDerivative(model, state, k1, step, out DormandPrince54Step slow);
                        Assert.That(accepted, Is.EqualTo(reference), $"{state}");
                        AssertSame(fast.End, slow.End, state);
                        AssertSame(fast.EndDerivative.Velocity, slow.EndDerivative.Velocity, state);
                        AssertSame(fast.EndDerivative.Acceleration, slow.EndDerivative.Acceleration, state);
                        AssertSame(fast.EndDerivative.AngularAcceleration, slow.EndDerivative.AngularAcceleration, state);
                        Assert.That(Same(fast.ErrorNorm, slow.ErrorNorm), Is.True, $"error norm {fast.ErrorNorm} != {slow.ErrorNorm} from {state}");
                        Assert.That(Same(fast.NextStep, slow.NextStep), Is.True, $"next step {fast.NextStep} != {slow.NextStep} from {state}");
                        if (fast.End.IsFinite)
                        {
                            foreach (double theta in new[] { 0.125, 0.37, 0.5, 0.9 })
                            {
                                AssertSame(fast.InterpolateFraction(theta), slow.InterpolateFraction(theta), state);
                            }
                        }

                        FlightState fixedEnd = ((IIntegrator)method).Step(model, state, k1, step, out StateDerivative fixedDerivative, out int evaluations);
                        AssertSame(fixedEnd, slow.End, state);
                        AssertSame(fixedDerivative.Acceleration, slow.EndDerivative.Acceleration, state);
                        Assert.That(evaluations, Is.EqualTo(6));
                        compared++;
                    }
                }
            }

            Assert.That(compared, Is.EqualTo(205 * 3 * 3));
        }

        [TestCaseSource(nameof(Models))]
        public void Dp54Stages_EqualTheTableauThroughTheGeneralFormula_BitForBit(FlightModel model, string laws)
        {
            // Unfolded laws: the tableau on the general derivative; folded ones: on the kernel's own (folded) derivative
            // (which ConformanceTests holds to the general formula within its bound). Bit for bit either way.
            Func<FlightState, StateDerivative> spec = Folded(laws) ? s => FlightKernel.DerivativeOf(model, s) : s => model.GeneralDerivative(s);
            int finiteSteps = 0;
            foreach (FlightState state in States())
            {
                foreach (double step in new[] { 1.0 / 240, 0.03 })
                {
                    StateDerivative k1 = spec(state);
                    FlightState reference = ReferenceDp54(model, state, k1, step, out StateDerivative[] k, spec);
                    // Stages that hold garbage beforehand: the kernel writes every stage it reads (k2..k6 from the stages
                    // themselves), so nothing left in them may reach the step.
                    DormandPrince54Stages stages = Garbage();
                    bool finite = FlightKernel.Of(model).DormandPrince54(state, k1, step, ref stages);
                    if (finite)
                    {
                        finiteSteps++;
                        AssertSame(stages.End, reference, state);
                        StateDerivative[] written = { Rates(stages.K2), Rates(stages.K3), Rates(stages.K4), Rates(stages.K5), Rates(stages.K6), stages.K7 };
                        for (int i = 0; i < written.Length; i++)
                        {
                            AssertSame(written[i].Velocity, k[i].Velocity, state);
                            AssertSame(written[i].Acceleration, k[i].Acceleration, state);
                            AssertSame(written[i].AngularAcceleration, k[i].AngularAcceleration, state);
                        }
                    }
                }
            }

            // The kernel reports a step not finite (so DormandPrince54 redoes it through FlightModel.Derivative) only where a
            // stage overflows: none of these states and steps comes near that.
            Assert.That(finiteSteps, Is.EqualTo(205 * 2));
        }

        [Test]
        public void Dp54Step_WhereAStageOverflows_IsTheStepThroughDerivative()
        {
            // Speeds whose drag overflows a double inside the step: the kernel reports it (false) and DormandPrince54 redoes
            // the step through FlightModel.Derivative, so the outcome is what it was before the kernel, whatever it is.
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            int fallbacks = 0;
            foreach (double speed in new[] { 1e100, 1e150, 1e153, 1e154, 1e155, 1e200, 1e300 })
            {
                var state = new FlightState(new Vector3d(0, 0, 1), new Vector3d(speed, 0, speed / 3), new Vector3d(10, 150, 20));
                StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                DormandPrince54Stages ignored = default;
                if (!FlightKernel.Of(model).DormandPrince54(state, k1, 0.01, ref ignored))
                {
                    fallbacks++;
                }

                bool accepted = DormandPrince54.Instance.TryStep(model, state, k1, 0.01, out DormandPrince54Step fast);
                bool reference = DormandPrince54.Instance.TryStepThroughDerivative(model, state, k1, 0.01, out DormandPrince54Step slow);
                Assert.That(accepted, Is.EqualTo(reference));
                AssertSame(fast.End, slow.End, state);
                AssertSame(fast.EndDerivative.Acceleration, slow.EndDerivative.Acceleration, state);
                Assert.That(Same(fast.ErrorNorm, slow.ErrorNorm) && Same(fast.NextStep, slow.NextStep), Is.True, $"{state}");
            }

            Assert.That(fallbacks, Is.GreaterThan(0), "some of these steps overflow in the kernel");
        }

        [Test]
        public void Dp54KernelStep_EvaluatesTheModelSixTimes_AndAUserLawOnceEach()
        {
            var drag = new CountingDrag();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative k1 = FlightKernel.DerivativeOf(model, start);
            calls.Calls = 0;
            drag.Calls = 0;
            DormandPrince54.Instance.TryStep(model, start, k1, 0.01, out _);
            Assert.That(calls.Calls, Is.EqualTo(6));
            Assert.That(drag.Calls, Is.EqualTo(6));
        }

        [Test]
        public void FoldedRk4AndHeunSteps_AreTheFormulaOnTheFoldedDerivative_BitForBit()
        {
            // The folded kernels' RK4 and Heun are the RungeKutta4/Heun arithmetic on the kernel's own (folded) derivative,
            // exactly: only the derivative differs from the general formula (in rounding, tested above), not the step.
            foreach (FlightModel model in new[]
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp),
                FlightModel.Thesis(Ball.Tennis, new Air(1.21, new Vector3d(3, -2, 0.5)), Gravity.ZUp),
                new FlightModel(Ball.Tennis, new Air(1.2).WithLogarithmicWind(new Vector3d(6, 1, 0)), Gravity.ZUp,
                    ConstantDrag.CrossLindseyTennis, new ConstantLift(-0.3), new ExponentialSpinDecay(3)),
            }.Concat(StepanekLiftModels()))
            {
                foreach (FlightState state in States().Concat(StatesOutsideTheFold(model).Skip(2)))
                {
                    foreach (double step in new[] { 1.0 / 240, 0.03 })
                    {
                        StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                        FlightState rk4 = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k1, step, out StateDerivative rk4End, out _);
                        FlightState heun = ((IIntegrator)Heun.Instance).Step(model, state, k1, step, out StateDerivative heunEnd, out _);
                        FlightState rk4Reference = ReferenceRk4(model, state, k1, step, s => FlightKernel.DerivativeOf(model, s));
                        FlightState heunReference = ReferenceHeun(model, state, k1, step, s => FlightKernel.DerivativeOf(model, s));
                        AssertSame(rk4, rk4Reference, state);

                        AssertSame(heun, heunReference, state);
                        if (rk4.IsFinite)
                        {
                            // The end rates are the derivative at the end state, bit for bit.
                            AssertSame(rk4End.Acceleration, FlightKernel.DerivativeOf(model, rk4).Acceleration, state);
                            AssertSame(rk4End.AngularAcceleration, FlightKernel.DerivativeOf(model, rk4).AngularAcceleration, state);
                        }

                        if (heunReference.IsFinite)
                        {
                            AssertSame(heunEnd.Acceleration, FlightKernel.DerivativeOf(model, heunReference).Acceleration, state);
                        }
                    }
                }
            }
        }

        private static double Ulp(double value) => Rounding.Ulp(value);

        [Test]
        public void StraightLineRk4_OfTheThesisModel_IsTheGeneralStep_BitForBit()
        {
            // Mono takes RK4's straight-line form for the thesis model's common case (FlightKernel.PreferStraightLine),
            // CoreCLR the general one; this runs the straight-line form on every runtime against the general step and the
            // reference RK4 on the kernel's derivative. It must take the common case for most states (it would be no use
            // otherwise) and decline the ones outside it: no spin, wind, a spin-decay law.
            var still = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var yUp = FlightModel.Thesis(Ball.Soccer, new Air(1.18), Gravity.YUp);
            int taken = 0, declined = 0;
            foreach (FlightModel model in new[] { still, yUp })
            {
                foreach (FlightState state in States())
                {
                    foreach (double step in new[] { 1.0 / 240, 0.03, 1e-9 })
                    {
                        StateDerivative k1 = FlightKernel.DerivativeOf(model, state);
                        FlightState general = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k1, step, out StateDerivative generalEnd, out _);
                        if (!FlightKernel.Of(model).TryRk4StraightLine(state, k1, step, out FlightState straight, out StateDerivative straightEnd))
                        {
                            declined++;
                            continue;
                        }

                        taken++;
                        AssertSame(straight, general, state);
                        AssertSame(straight, ReferenceRk4(model, state, k1, step, s => FlightKernel.DerivativeOf(model, s)), state);
                        AssertSame(straightEnd.Acceleration, generalEnd.Acceleration, state);
                        AssertSame(straightEnd.AngularAcceleration, generalEnd.AngularAcceleration, state);
                    }
                }
            }

            Assert.That(taken, Is.GreaterThan(0.9 * (taken + declined)), $"taken {taken}, declined {declined}");
            var spinless = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), default);
            var spinning = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            Assert.That(FlightKernel.Of(still).TryRk4StraightLine(spinless, FlightKernel.DerivativeOf(still, spinless), 1.0 / 240, out _, out _), Is.False, "no spin");
            var windy = FlightModel.Thesis(Ball.Tennis, new Air(1.21, new Vector3d(3, 0, 0)), Gravity.ZUp);
            Assert.That(FlightKernel.Of(windy).TryRk4StraightLine(spinning, FlightKernel.DerivativeOf(windy, spinning), 1.0 / 240, out _, out _), Is.False, "wind");
            var decaying = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, ConstantDrag.CrossLindseyTennis, new ConstantLift(0.2), new ExponentialSpinDecay(3));
            Assert.That(FlightKernel.Of(decaying).TryRk4StraightLine(spinning, FlightKernel.DerivativeOf(decaying, spinning), 1.0 / 240, out _, out _), Is.False, "spin decay");
        }

        [Test]
        public void StraightLineRk4_OnAdversarialStates_IsTheGeneralStep_BitForBit()
        {
            // The corners of Rk4Straight against Rk4Unrolled, compared bit for bit (signed zeros too, unlike AssertSame):
            // components +-0, subnormal, near the aerodynamic cut-off 1e-150, near 1e154 (where squares overflow) and
            // huge; spins from subnormal (1/|w| overflows) to 1e308 (|w| through LengthOf's scaled path); gravity with -0
            // components (Gravity.Along) and y-up; steps from 1e-300 to 1e3. A counter on the general model makes RK4 take
            // Rk4Unrolled on every runtime (PreferStraightLine skips the straight form where a counter is attached).
            double[] magnitudes =
            {
                0, 5e-324, 1e-310, 2.2250738585072014e-308, 1e-300, 1e-160, 1e-151, 1e-150, 1.0000000000000002e-150,
                1.5e-150, 1e-100, 1e-5, 0.3, 5, 30, 150, 1e100, 1e153, 0.9e154, 1.0e154, 1.34e154, 1e200, 1e300, 1.7e308,
            };
            var random = new Random(11);
            double Component() =>
                random.NextDouble() < 0.3 ? (random.NextDouble() - 0.5) * 80 : (random.NextDouble() < 0.5 ? -1 : 1) * magnitudes[random.Next(magnitudes.Length)];
            Vector3d Vector() => new Vector3d(Component(), Component(), Component());
            var models = new[]
            {
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp),
                FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.Along(Vector3d.UnitZ)), // gravity (-0, -0, -9.8)
                FlightModel.Thesis(Ball.Soccer, new Air(1.18), Gravity.Along(Vector3d.UnitY)),
                FlightModel.Thesis(Ball.Tennis, new Air(1e-300), Gravity.Along(new Vector3d(1, -2, 3), 1e-3)),
            };
            double[] steps = { 1e-300, 1e-30, 1e-9, 1.0 / 240, 0.03, 1, 1e3 };
            int taken = 0, compared = 0;
            foreach (FlightModel model in models)
            {
                var general = new FlightModel(model.Ball, model.Air, model.Gravity, model.Drag, model.Lift, model.SpinDecay)
                {
                    CountedEvaluations = new EvaluationCount(),
                };
                for (int i = 0; i < 3000; i++)
                {
                    var state = new FlightState(Vector(), Vector(), Vector(), random.NextDouble());
                    if (i % 5 == 0)
                    {
                        // a realistic flight with signed-zero spin components (a negated spin vector, e.g. -(0, -150, 0))
                        state = new FlightState(
                            new Vector3d(0, 0, 1), new Vector3d(30, 0, -5), -new Vector3d(0, random.Next(-300, 300), random.Next(-2, 2)));
                    }

                    StateDerivative k1 = FlightKernel.DerivativeOf(general, state);
                    if (i % 7 == 3)
                    {
                        // a start spin rate the model does not have (outside IIntegrator.Step's contract; both forms still agree)
                        k1 = new StateDerivative(k1.Velocity, k1.Acceleration, new Vector3d(random.NextDouble() - 0.5, -0.0, 40 * random.NextDouble()));
                    }

                    double step = steps[i % steps.Length];
                    compared++;
                    FlightState expected = ((IIntegrator)RungeKutta4.Instance).Step(general, state, k1, step, out StateDerivative expectedEnd, out _);
                    if (!FlightKernel.Of(model).TryRk4StraightLine(state, k1, step, out FlightState straight, out StateDerivative straightEnd))
                    {
                        continue;
                    }

                    taken++;
                    AssertSameStep(straight, straightEnd, expected, expectedEnd, state, step);
                }
            }

            // Most random states leave the common case somewhere (a tiny or overflowing stage speed); enough take it.
            Assert.That(taken, Is.GreaterThan(compared / 5), $"taken {taken} of {compared}");
        }

        [Test]
        public void StraightLineRk4_OfStepanekTennis_IsTheGeneralStep_BitForBit()
        {
            // Mono takes a straight-line form of RK4 for Stepanek's drag and lift folded in still air (any spin decay):
            // FlightKernel.Rk4StraightStepanek. It must be Rk4Loop's step bit for bit (signed zeros too) wherever it answers,
            // on every runtime: a counter on the general model makes RK4 take Rk4Loop (the straight form is skipped where a
            // counter is attached). Exponential decays with steps within and beyond one time constant, the presets'
            // speed-proportional decay and no decay. States: realistic flights (speeds 0.5-70 m/s, spins to 600 rad/s in any direction, some with signed-zero
            // components, steps from 1e-9 to 0.07 s), adversarial ones (components from subnormal to 1e308, steps to 30 s),
            // and the two ends of the fold's |w x v|^2 range.
            double[] magnitudes = { 0, 5e-324, 1e-310, 1e-160, 1e-60, 1e-30, 1e-5, 0.3, 5, 30, 150, 1e30, 1e60, 1e154, 1e200, 1.7e308 };
            var random = new Random(23);
            double Component() =>
                random.NextDouble() < 0.3 ? (random.NextDouble() - 0.5) * 80 : (random.NextDouble() < 0.5 ? -1 : 1) * magnitudes[random.Next(magnitudes.Length)];
            Vector3d Vector() => new Vector3d(Component(), Component(), Component());
            Vector3d Direction() => new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            var models = new[]
            {
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20)),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.Along(Vector3d.UnitY), StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(0.05)),
                new FlightModel(Ball.Tennis, new Air(1.18), Gravity.YUp, StepanekDrag.Instance, StepanekLift.Instance, SpeedProportionalSpinDecay.TennisCrossLindsey),
                new FlightModel(Ball.Tennis, new Air(1.21), Gravity.Along(new Vector3d(1, -2, 3)), StepanekDrag.Instance, StepanekLift.Instance),
            };
            double[] steps = { 1e-9, 1.0 / 240, 0.03, 0.07, 1, 30 }; // 0.07 s: 1.4 time constants of the second model
            int taken = 0, compared = 0, realisticTaken = 0, realistic = 0;
            foreach (FlightModel model in models)
            {
                var general = new FlightModel(model.Ball, model.Air, model.Gravity, model.Drag, model.Lift, model.SpinDecay)
                {
                    CountedEvaluations = new EvaluationCount(),
                };
                for (int i = 0; i < 2500; i++)
                {
                    bool isRealistic = i % 2 == 0;
                    FlightState state = isRealistic
                        ? new FlightState(
                            Vector(), Direction().NormalizedOrZero() * (0.5 + 69.5 * random.NextDouble()),
                            i % 10 == 0 ? -new Vector3d(0, random.Next(-600, 600), 0) : Direction() * (1200 * random.NextDouble()),
                            random.NextDouble())
                        : new FlightState(Vector(), Vector(), Vector(), random.NextDouble());
                    double step = isRealistic ? steps[random.Next(4)] : steps[i % steps.Length];
                    if (i % 8 == 1)
                    {
                        // The fold's |w x v|^2 range at its two ends: a velocity almost along the spin (|w x v|^2 near 1e-206,
                        // below the range but not 0), and |w| = 1e50 against 1e51 m/s (|w x v|^2 = 1e202, above it) over a
                        // step too short to move the velocity, where nothing else leaves the fold.
                        Vector3d axis = Direction().NormalizedOrZero();
                        Vector3d across = Vector3d.Cross(axis, Vector3d.UnitX).NormalizedOrZero();
                        state = i % 16 == 1
                            ? new FlightState(Vector(), axis * (5 + 55 * random.NextDouble()) + across * 1e-105, axis * (10 + 590 * random.NextDouble()))
                            : new FlightState(Vector(), new Vector3d(1e51, 0, 0), new Vector3d(0, 1e50, 0));
                        step = i % 16 == 1 ? steps[random.Next(3)] : 1e-300;
                    }

                    StateDerivative k1 = FlightKernel.DerivativeOf(general, state);
                    compared++;
                    realistic += isRealistic ? 1 : 0;
                    FlightState expected = ((IIntegrator)RungeKutta4.Instance).Step(general, state, k1, step, out StateDerivative expectedEnd, out _);
                    if (!FlightKernel.Of(model).TryRk4StraightLine(state, k1, step, out FlightState straight, out StateDerivative straightEnd))
                    {
                        continue;
                    }

                    taken++;
                    realisticTaken += isRealistic ? 1 : 0;
                    AssertSameStep(straight, straightEnd, expected, expectedEnd, state, step);
                }
            }

            // Realistic flights take it (a spinning ball at a game's speeds; the spinless ones, 1 in 1,200 or so, do not);
            // adversarial ones mostly leave the fold's range or the table somewhere.
            TestContext.WriteLine($"taken {taken} of {compared}; realistic {realisticTaken} of {realistic}");
            Assert.That(realisticTaken, Is.GreaterThan(0.95 * realistic), $"realistic taken {realisticTaken} of {realistic}");
            Assert.That(taken, Is.GreaterThan(realisticTaken), "some adversarial states take it too");

            // Declined: no spin, wind, a spin parameter off the table at every stage (z below 2^-44: 1 m/s against 1e9 rad/s), a spin
            // past the fold's range, and laws it is not written for (constant drag).
            FlightModel tennis = models[0];
            var spinless = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), default);
            var offTable = new FlightState(new Vector3d(0, 0, 1), new Vector3d(1, 0, 0), new Vector3d(0, 1e9, 0));
            var pastFold = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(0, 1e60, 0));
            var spinning = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            foreach ((string why, FlightModel model, FlightState state) in new[]
            {
                ("no spin", tennis, spinless),
                ("off the table", tennis, offTable),
                ("past the fold", tennis, pastFold),
                ("wind", new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(3, 0, 0)), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance), spinning),
                ("constant drag", new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, new ConstantDrag(0.55), StepanekLift.Instance), spinning),
            })
            {
                Assert.That(FlightKernel.Of(model).TryRk4StraightLine(state, FlightKernel.DerivativeOf(model, state), 1.0 / 240, out _, out _), Is.False, why);

                // A declined step leaves the caller's derivative for the general step, where the caller passes one variable
                // as the start and end derivative (StableStepping does): the same step as with two variables. (Under Mono,
                // where RK4 tries the straight form first, an early version zeroed it and the step lost its first slope.)
                StateDerivative separate = FlightKernel.DerivativeOf(model, state), shared = separate;
                FlightState apart = ((IIntegrator)RungeKutta4.Instance).Step(model, state, separate, 1.0 / 240, out StateDerivative end, out _);
                FlightState together = ((IIntegrator)RungeKutta4.Instance).Step(model, state, shared, 1.0 / 240, out shared, out _);
                AssertBits(together.Velocity, apart.Velocity, state, 1.0 / 240);
                AssertBits(shared.Acceleration, end.Acceleration, state, 1.0 / 240);
            }
        }

        // A straight-line step against the general one, every number bit for bit (signed zeros too).
        private static void AssertSameStep(
            in FlightState straight, in StateDerivative straightEnd, in FlightState expected, in StateDerivative expectedEnd, in FlightState from, double step)
        {
            AssertBits(straight.Position, expected.Position, from, step);
            AssertBits(straight.Velocity, expected.Velocity, from, step);
            AssertBits(straight.AngularVelocity, expected.AngularVelocity, from, step);
            AssertBits(straightEnd.Velocity, expectedEnd.Velocity, from, step);
            AssertBits(straightEnd.Acceleration, expectedEnd.Acceleration, from, step);
            AssertBits(straightEnd.AngularAcceleration, expectedEnd.AngularAcceleration, from, step);
            Assert.That(BitConverter.DoubleToInt64Bits(straight.Time), Is.EqualTo(BitConverter.DoubleToInt64Bits(expected.Time)));
        }

        private static void AssertBits(in Vector3d actual, in Vector3d expected, in FlightState from, double step)
        {
            if (BitConverter.DoubleToInt64Bits(actual.X) != BitConverter.DoubleToInt64Bits(expected.X)
                || BitConverter.DoubleToInt64Bits(actual.Y) != BitConverter.DoubleToInt64Bits(expected.Y)
                || BitConverter.DoubleToInt64Bits(actual.Z) != BitConverter.DoubleToInt64Bits(expected.Z))
            {
                Assert.Fail($"straight {Bits(actual)} != general {Bits(expected)} from {Bits(from.Position)} {Bits(from.Velocity)} {Bits(from.AngularVelocity)}, step {step:R}");
            }
        }

        private static string Bits(in Vector3d v) => $"({v.X:R}, {v.Y:R}, {v.Z:R})";

        // RungeKutta4.Advance alternates two pairs of locals; odd counts end on the other pair (0, 1 and 479 included).
        [TestCase(false, 480)]
        [TestCase(false, 479)]
        [TestCase(false, 1)]
        [TestCase(false, 0)]
        [TestCase(true, 480)]
        [TestCase(true, 479)]
        public void Advance_EqualsOneStepAtATime_BitForBit(bool thesis, int count)
        {
            var air = new Air(1.21).WithLogarithmicWind(new Vector3d(5, 0, 0));
            FlightModel model = thesis
                ? FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp)
                : new FlightModel(Ball.Tennis, air, Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative run = FlightKernel.DerivativeOf(model, start);
            FlightState many = start;
            int taken = RungeKutta4.Instance.Advance(model, ref many, ref run, 1.0 / 240, count);
            Assert.That(taken, Is.EqualTo(count));
            FlightState one = start;
            StateDerivative k = FlightKernel.DerivativeOf(model, start);
            for (int i = 0; i < count; i++)
            {
                one = ((IIntegrator)RungeKutta4.Instance).Step(model, one, k, 1.0 / 240, out k, out _);
            }

            AssertSame(many, one, start);
            AssertSame(run.Velocity, k.Velocity, start);
            AssertSame(run.Acceleration, k.Acceleration, start);
            AssertSame(run.AngularAcceleration, k.AngularAcceleration, start);
        }

        [Test]
        public void Advance_EvaluatesTheModelFourTimesAStep()
        {
            var drag = new CountingDrag();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var calls = new EvaluationCount();
            model.CountedEvaluations = calls;
            var state = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative k = FlightKernel.DerivativeOf(model, state);
            calls.Calls = 0;
            drag.Calls = 0;
            int taken = RungeKutta4.Instance.Advance(model, ref state, ref k, 1.0 / 240, 37);
            Assert.That(taken, Is.EqualTo(37));
            Assert.That(calls.Calls, Is.EqualTo(4 * 37));
            Assert.That(drag.Calls, Is.EqualTo(4 * 37));
        }

        [Test]
        public void Advance_TakesItsLargestCount()
        {
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var state = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative k = FlightKernel.DerivativeOf(model, state);
            Assert.That(RungeKutta4.MaximumAdvanceSteps, Is.EqualTo(250_000));
            Assert.That(RungeKutta4.Instance.Advance(model, ref state, ref k, 1.0 / 240, RungeKutta4.MaximumAdvanceSteps), Is.EqualTo(250_000));
            Assert.That(state.Time, Is.EqualTo(250_000 / 240.0).Within(1e-6), "17 minutes of flight (falling at its terminal speed)");
        }

        [TestCase(-1, 1.0 / 240, "count")]
        [TestCase(250_001, 1.0 / 240, "count")]
        [TestCase(10, 0.0, "step")]
        [TestCase(10, double.NaN, "step")]
        [TestCase(10, double.PositiveInfinity, "step")]
        public void Advance_RefusesBadArguments_AndChangesNothing(int count, double step, string parameter)
        {
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative startRates = FlightKernel.DerivativeOf(model, start);
            FlightState state = start;
            StateDerivative rates = startRates;
            var error = Assert.Throws(Is.InstanceOf<ArgumentException>(), () => RungeKutta4.Instance.Advance(model, ref state, ref rates, step, count));
            Assert.That(((ArgumentException)error!).ParamName, Is.EqualTo(parameter));
            Assert.That(error.Message, Does.Contain(parameter == "count" ? "[0, 250000]" : "> 0"));
            AssertSame(state, start, start);
            AssertSame(rates.Acceleration, startRates.Acceleration, start);
        }

        [Test]
        public void Advance_RefusesANonFiniteStateOrNoModel_AndChangesNothing()
        {
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, double.NaN, 1), new Vector3d(30, 1, 5), Vector3d.Zero);
            FlightState state = start;
            StateDerivative rates = default;
            var error = Assert.Throws(Is.InstanceOf<ArgumentException>(), () => RungeKutta4.Instance.Advance(model, ref state, ref rates, 0.01, 5));
            Assert.That(((ArgumentException)error!).ParamName, Is.EqualTo("state"));
            Assert.That(double.IsNaN(state.Position.Y) && state.Position.X == 0 && state.Velocity.X == 30, Is.True);
            Assert.Throws<ArgumentNullException>(() => RungeKutta4.Instance.Advance(null!, ref state, ref rates, 0.01, 5));
        }

        [Test]
        public void Advance_StopsBeforeTheFirstStepThatIsNotFinite()
        {
            // Half-second steps of a tennis ball at 236 m/s: past RK4's stability limit for its drag (it flies on at 234 m/s),
            // so each step's speed grows until the fifth overflows. Advance stops before it, on the last finite state, and
            // says how many steps it took: from three starts (4, 3 and 0 finite steps left) and for counts around the
            // overflow (0-6 and 1,000), which reach each of its exits (the first step, either step of a pair, the odd last step).
            FlightModel model = FlightModel.Thesis(Ball.Tennis, new Air(1.21), Gravity.ZUp);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(236, 1, 5), new Vector3d(10, 150, 20));
            var states = new List<FlightState> { start };
            var rates = new List<StateDerivative> { FlightKernel.DerivativeOf(model, start) };
            while (true)
            {
                FlightState next = ((IIntegrator)RungeKutta4.Instance).Step(model, states[^1], rates[^1], 0.5, out StateDerivative end, out _);
                if (!(next.IsFinite && end.IsFinite))
                {
                    break;
                }

                states.Add(next);
                rates.Add(end);
                Assert.That(states.Count, Is.LessThan(1000), "the steps overflow");
            }

            int finite = states.Count - 1; // the steps that stay finite from the start
            Assert.That(finite, Is.EqualTo(4), "four steps before the overflow");
            foreach (int offset in new[] { 0, 1, finite })
            {
                int left = finite - offset;
                foreach (int count in new[] { 0, 1, 2, 3, 4, 5, 6, 1000 })
                {
                    FlightState state = states[offset];
                    StateDerivative k = rates[offset];
                    int taken = RungeKutta4.Instance.Advance(model, ref state, ref k, 0.5, count);
                    int expected = Math.Min(count, left);
                    Assert.That(taken, Is.EqualTo(expected), $"offset {offset}, count {count}");
                    AssertSame(state, states[offset + expected], start);
                    AssertSame(k.Acceleration, rates[offset + expected].Acceleration, start);
                }
            }
        }

        [Test]
        public void UserLaw_IsCalledOncePerEvaluation()
        {
            var drag = new CountingDrag();
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, drag);
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            StateDerivative k = FlightKernel.DerivativeOf(model, start);
            FlightState state = start;
            int evaluations = 1;
            for (int i = 0; i < 100; i++)
            {
                state = ((IIntegrator)RungeKutta4.Instance).Step(model, state, k, 1.0 / 240, out k, out int used);
                evaluations += used;
            }

            Assert.That(drag.Calls, Is.EqualTo(evaluations));
            Assert.That(drag.Calls, Is.EqualTo(401));
        }

        [Test]
        public void KernelSteps_AllocateZeroBytes()
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21), Gravity.ZUp, StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(20));
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));
            FlightState end = default;
            Action steps = () =>
            {
                end = start;
                StateDerivative k = FlightKernel.DerivativeOf(model, start);
                RungeKutta4.Instance.Advance(model, ref end, ref k, 1.0 / 240, 480);
            };
            long allocated = Allocation.SteadyStateBytes(steps);
            Assert.That(allocated, Is.EqualTo(0));
            Assert.That(end.IsFinite, Is.True);
        }

        // The textbook steps (Textbook.cs) on the general derivative, or on the rates given.
        private static FlightState ReferenceRk4(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step, Func<FlightState, StateDerivative>? rates = null) =>
            Textbook.Rk4(rates ?? (s => model.GeneralDerivative(s)), state, derivative, step);

        private static FlightState ReferenceDp54(
            FlightModel model, in FlightState y, in StateDerivative k1, double h, out StateDerivative[] k, Func<FlightState, StateDerivative>? rates = null) =>
            Textbook.Dp54(rates ?? (s => model.GeneralDerivative(s)), y, k1, h, out k);

        private static FlightState ReferenceHeun(
            FlightModel model, in FlightState state, in StateDerivative derivative, double step, Func<FlightState, StateDerivative>? rates = null) =>
            Textbook.Heun(rates ?? (s => model.GeneralDerivative(s)), state, derivative, step);

        private static StateDerivative Rates(in StageRates k) => new StateDerivative(k.Velocity, k.Acceleration, k.AngularAcceleration);

        private static DormandPrince54Stages Garbage()
        {
            var nan = new Vector3d(double.NaN, double.NaN, double.NaN);
            var rates = new StageRates { Velocity = nan, Acceleration = nan, AngularAcceleration = nan };
            return new DormandPrince54Stages
            {
                End = new FlightState(nan, nan, nan, double.NaN),
                K2 = rates,
                K3 = rates,
                K4 = rates,
                K5 = rates,
                K6 = rates,
                K7 = new StateDerivative(nan, nan, nan),
            };
        }

        private static void AssertSame(in FlightState actual, in FlightState expected, in FlightState from)
        {
            AssertSame(actual.Position, expected.Position, from);
            AssertSame(actual.Velocity, expected.Velocity, from);
            AssertSame(actual.AngularVelocity, expected.AngularVelocity, from);
            Assert.That(actual.Time, Is.EqualTo(expected.Time));
        }

        // Exact equality (NaN equal to NaN: a diverging step must diverge the same way).
        private static void AssertSame(in Vector3d actual, in Vector3d expected, in FlightState from)
        {
            if (!(Same(actual.X, expected.X) && Same(actual.Y, expected.Y) && Same(actual.Z, expected.Z)))
            {
                Assert.Fail($"kernel {actual} != general {expected} from {from}");
            }
        }

        private static bool Same(double a, double b) => BitConverter.DoubleToInt64Bits(a) == BitConverter.DoubleToInt64Bits(b) || (double.IsNaN(a) && double.IsNaN(b));
    }
}
