using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Fuzz
{
    /// <summary>A defect the shape fuzz found (docs/robustness.md, "Contact shapes"), replayed as the long run printed it.</summary>
    public class ShapeFuzzFindingsTests
    {
        [Test]
        public void ARollBegunAtAnExtremeState_WithANonFiniteDerivative_IsRefused_NotTaken()
        {
            // A hostile ball (2.7 g, 120 m across, in air of 96 kg/m^3) driven to 5e6 m/s by the calls before: one adaptive step's
            // piece reaches 1e272 m/s, bounces on the ground and starts rolling there, where the derivative overflows to NaN. The
            // step was taken with that NaN derivative (shape fuzz, seed 40); a step whose end derivative is not finite is refused.
            var model = new FlightModel(new Ball(0.0026832877125134826, 119.76900446455551, 0.5165202444961855), new Air(96.16700186955755, new Vector3d(-2.2762514524043698, -35.866098685955926, -0.010746525527499285)), new Vector3d(0, 0, -9.80665), StepanekDrag.Instance, new ConstantLift(-0.32608140894420234), new SpeedProportionalSpinDecay(0.2478344916641571));
            ContactShape[] shapes = [new BoxShape(0, new Vector3d(7.867010577054234, 3.803993216158819, 0.3212969567725886), new Vector3d(0.3624098085524755, 19.23465508290663, 0.00025418153594342714), new Vector3d(-0.8594298045178841, 0.5095700119489325, -0.04145858208762464), new Vector3d(-0.909837380105544, 0.41454959222369764, 0.018562794774655885), new ContactProperties(0.957145292291951, 0.7166697525962581, 0, 0.004589133227518356, 0.0013739630260383544, 0), double.PositiveInfinity), new BoxShape(1, new Vector3d(11.828024935362873, -3.9160213055629383, 2.121322051911299), new Vector3d(0.003066212646550431, 0.001902179541459983, 0.3023691075783124), new Vector3d(-0.132572227151405, 0.3909190672264974, -0.9108275838307058), new Vector3d(-0.8773404461232069, 0.47766031800480635, 0.0459821943786862), new ContactProperties(0.2020590897659115, 0.5903716588348018, 0, 0.0032936666874651176, 0, 4.827808684123591E-05), double.PositiveInfinity), new BoxShape(2, new Vector3d(-1.7134641002460684, -3.7530444416930173, 1.1968691822592492), new Vector3d(5.23035591185099, 0.001912982421989342, 2.261006369228314E-06), new Vector3d(0.8595744086636151, 0.04847666303471513, -0.508706053739893), new Vector3d(-0.9382037235592264, 0.26539132961357614, 0.22212882583208476), new ContactProperties(0.09486815850011453, 0.8459168886048333, 0, 0, 0, 9.385969820146435E-05), double.PositiveInfinity), BoxShape.Rectangle(3, new Vector3d(9.143512385964168, -1.790188176925382, 1.669346268367649), new Vector3d(-0.3441694352514981, 0.14951607456033034, 0.9269262879467465), new Vector3d(-0.5034393562203159, -0.863963426708811, 0.010770882881294224), 5.704586462506124, 0.0011712205068463014, new ContactProperties(0.4249332269769782, 0.7145644504179082, 0, 0.007378582711042176, -0.005921578498520692, 0), double.PositiveInfinity)];
            var stepper = new FlightStepper(model, Integrators.FromName("euler"), null, new GroundContact(CrossBounce.Grass, new Plane(new Vector3d(0, 0, 0), new Vector3d(-0, -0, 1)), 0.1, 0.03), shapes);
            stepper.Reset(new FlightState(new Vector3d(48.978974134148466, -22.188291215047542, -109.46032296393464), new Vector3d(0.17079565337042307, -0.09345737856409347, -0.10899895598341981), new Vector3d(-0, -0, 0), 0));
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.0038010973109438586, (FlightEventKinds)36);
            stepper.Reset(new FlightState(new Vector3d(-92.592262570081, 42.936863687740136, 37.42531430141406), new Vector3d(0.02137501585807142, -0.02633216623946465, -0.016766596795619114), new Vector3d(0.03697434113390732, -0.13685177957303046, 0.07742665589754087), 0));
            stepper.TryStep(0.025340335116406407, (FlightEventKinds)0);
            stepper.Reset(new FlightState(new Vector3d(-55.22209339512594, -35.36135347972048, 98.57342623236275), new Vector3d(0.02028396656188334, -0.05965974050433495, 0.07413781037423192), new Vector3d(0.2702653731509678, -0.5101087362068435, -0.8274101903499671), 707.6137721108337));
            stepper.TryStep(0.16344155881361822, (FlightEventKinds)0);
            stepper.Reset(new FlightState(new Vector3d(-45.62100639125385, -10.636074391508263, 108.61609312630172), new Vector3d(0.024158615564617805, -0.056700425887218034, -0.10904652013303555), new Vector3d(0.01472907537780024, -0.06206417953862402, -0.09176083493506478), 490.9357379614076));
            stepper.TryStep(0.14179641638491144, (FlightEventKinds)0);
            stepper.TryStep(0.015029290828312959, (FlightEventKinds)0);
            stepper.TryStep(1.4097203558306703E-05, (FlightEventKinds)1);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 2.1088189220912284E-05, (FlightEventKinds)0);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 1.2192933424361039, (FlightEventKinds)0);
            stepper.TryStep(0.00030593808798353084, (FlightEventKinds)0);
            stepper.Reset(new FlightState(new Vector3d(-38.589441677279154, -84.76038583796573, -79.11467384611755), new Vector3d(0, 0, -0), new Vector3d(-0, 0, 0), 546.3206258352476));
            stepper.SetState(new FlightState(new Vector3d(102.33039418295046, -71.47210726183624, 14.511930522345473), new Vector3d(0.37357657872322014, -1.0827165648907708, 1.04297821213829), new Vector3d(-0, 0, -0), 0));
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.001436408917212044, (FlightEventKinds)33);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.0002646809147724926, (FlightEventKinds)49);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.5264688158656554, (FlightEventKinds)31);
            stepper.TryStep(2.2482751498409077, (FlightEventKinds)0);
            stepper.TryStep(1.3543074463587574, (FlightEventKinds)30);
            stepper.TryStep(0.02332384011712248, (FlightEventKinds)0);
            stepper.TryStep(0.0004210144485900994, (FlightEventKinds)16);
            stepper.TryStep(0.010488221584859863, (FlightEventKinds)0);
            stepper.TryStep(0.012463279562730889, (FlightEventKinds)0);
            stepper.TryStep(0.006092972890595852, (FlightEventKinds)0);
            stepper.TryStep(4.366428537938911E-05, (FlightEventKinds)5);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.2244391170865451, (FlightEventKinds)0);
            stepper.TryStep(0.000582484597634033, (FlightEventKinds)0);
            stepper.TryStep(0.21687289348224892, (FlightEventKinds)0);
            stepper.TryStep(0.006490932715839704, (FlightEventKinds)0);
            stepper.TryStep(0.2607620274028193, (FlightEventKinds)0);
            stepper.TryStep(0.004283207728953824, (FlightEventKinds)0);
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.4029775417854495, (FlightEventKinds)0);
            stepper.TryStep(0.004840492423922483, (FlightEventKinds)0);
            stepper.TryStep(2.8693441959727104E-05, (FlightEventKinds)0);
            stepper.SetState(new FlightState(new Vector3d(-30.69194936662886, 18.607914863112036, 112.79901551254365), new Vector3d(-0.0003271012004024957, -0.008193106164944189, 0.0016167794894328693), new Vector3d(-0.8506953848752263, -0.3603776527054767, -0.36055024267041835), 357.72165439916853));
            stepper.SetState(new FlightState(new Vector3d(25.230008263588875, 41.64660836238545, 114.25654788328904), new Vector3d(-0.12174144529826368, -0.06374992352815982, 0.06538213118461964), new Vector3d(0, 0, 0), 638.4032925769701));
            stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.0016196716631982733, (FlightEventKinds)0);
            stepper.TryStep(1.0057153029136177E-05, (FlightEventKinds)0);
            stepper.TryStep(0.002619818245469173, (FlightEventKinds)0);
            stepper.TryStep(0.009591700707199616, (FlightEventKinds)2);
            stepper.TryStep(0.9233277138459632, (FlightEventKinds)14);
            stepper.TryStep(3.1580592719730882, (FlightEventKinds)9);
            StepOutcome outcome = stepper.TryStepAdaptive(new DormandPrince54(3.600413070979806E-08, 3.6004130709798066E-11), 0.041449753925229364);
            Assert.That(outcome == StepOutcome.Diverged || (stepper.State.IsFinite && stepper.Derivative.IsFinite), Is.True, $"{outcome}: {stepper.Derivative.Acceleration}");
            Assert.That(stepper.Derivative.IsFinite, Is.True);
        }
    }
}
