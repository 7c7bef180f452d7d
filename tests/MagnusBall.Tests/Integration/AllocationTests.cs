using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Integration
{
    /// <summary>The hot path allocates nothing.</summary>
    [TestFixture]
    public class AllocationTests
    {
        [TestCaseSource(typeof(Integrators), nameof(Integrators.All))]
        public void TenThousandSteps_AllocateZeroBytes(IIntegrator integrator)
        {
            var model = new FlightModel(Ball.Tennis, new Air(1.21, new Vector3d(1, 2, 0)), Gravity.ZUp,
                StepanekDrag.Instance, StepanekLift.Instance, new ExponentialSpinDecay(5));
            var start = new FlightState(new Vector3d(0, 0, 1), new Vector3d(30, 1, 5), new Vector3d(10, 150, 20));

            FlightState end = default;
            Action fly = () => end = Shots.Fly(model, integrator, start, 1e-4, 10_000);
            long allocated = Allocation.SteadyStateBytes(fly);

            Assert.That(allocated, Is.EqualTo(0), $"{integrator.Name}: bytes allocated over 10,000 steps");
            Assert.That(end.IsFinite, Is.True);
        }
    }
}
