#nullable enable
using System;
using MagnusBall.Contact;
using UnityEngine;

namespace MagnusBall.Components
{
    /// <summary>What <see cref="MagnusBallRigidbody"/> does with the ball's spin when PhysX reports a collision.</summary>
    public enum SpinAtContact
    {
        /// <summary>
        /// The library's bounce model (the settings' surface) decides: from the velocity and spin before the
        /// contact and the contact normal it gives the velocity and spin after, and both replace PhysX's
        /// response. Falls back to <see cref="Keep"/> when the settings have no bounce.
        /// </summary>
        BounceModel = 0,

        /// <summary>PhysX's velocity response stands and the library's spin is kept unchanged (set it with <see cref="MagnusBallRigidbody.SetSpin"/>).</summary>
        Keep = 1,
    }

    /// <summary>
    /// Adds MagnusBall's aerodynamics (drag and the Magnus force, with the preset's spin decay) to a Rigidbody,
    /// for scenes that want PhysX collisions (rackets, walls, players). PhysX moves the body; every
    /// <c>FixedUpdate</c> this component adds the library's aerodynamic acceleration with
    /// <c>Rigidbody.AddForce(..., ForceMode.Acceleration)</c> and integrates the spin itself.
    /// </summary>
    /// <remarks>
    /// <para><b>Spin.</b> The spin lives in this component (<see cref="Spin"/>), never in
    /// <c>Rigidbody.angularVelocity</c>, which PhysX clips at <c>maxAngularVelocity</c> (by default
    /// <c>Physics.defaultMaxAngularSpeed</c>: 50 rad/s in a new project from Unity 2022, 7 rad/s before; a tennis ball
    /// spins at 100-400 rad/s). The Rigidbody's own angular velocity is left to PhysX.</para>
    /// <para><b>Force.</b> The acceleration added is the model's total acceleration minus the gravity PhysX
    /// already applies (<c>Physics.gravity</c> when <c>useGravity</c>, else none), so the body accelerates as the
    /// model says even if <c>Physics.gravity</c> differs from the model's gravity (Unity's default -9.81 against
    /// the library's standard 9.80665).</para>
    /// <para><b>Collisions.</b> In <c>OnCollisionEnter</c>, with <see cref="SpinAtContact.BounceModel"/>, the
    /// bounce model is applied at the first contact's normal to the velocity (relative to the other body, if it
    /// has a Rigidbody) and spin recorded at the last <c>FixedUpdate</c>, and the result is written back to
    /// <c>linearVelocity</c> and to <see cref="Spin"/>: the spin comes back from the contact as Cross's model
    /// says. With <see cref="SpinAtContact.Keep"/> PhysX's response stands and the spin is unchanged. Unity sends
    /// <c>OnCollisionEnter</c> only to a body with a collider (a SphereCollider of the ball's radius): the component
    /// requires the Rigidbody, not the collider, so add one.</para>
    /// <para><b>Accuracy.</b> PhysX integrates semi-implicitly at <c>Time.fixedDeltaTime</c>; docs/unity.md
    /// gives the landing error of this path against RK4 at 1/240 s (centimetres at 0.02 s). For the exact
    /// path use <see cref="MagnusBallFlight"/>.</para>
    /// <para><b>Inspector edits</b> take effect at once, also during Play (<c>OnValidate</c>): the next physics step uses the
    /// new settings. A refused value is reported once in the Console, naming the field; the previous settings stay.</para>
    /// <para><b>Dependency.</b> Rigidbody, Collision and ForceMode are the Physics module's (com.unity.modules.physics, which
    /// the package declares).</para>
    /// </remarks>
    [AddComponentMenu("MagnusBall/Rigidbody Aerodynamics")]
    [RequireComponent(typeof(Rigidbody))]
    [DisallowMultipleComponent]
    [HelpURL(UnityFrame.ManualUrl + "#rigidbody-aerodynamics")]
    public class MagnusBallRigidbody : MonoBehaviour
    {
        /// <summary>The ball, its aerodynamics, the air and the bounce used at contacts.</summary>
        public FlightSettings settings = new FlightSettings();

        /// <summary>What a collision does to the spin.</summary>
        [Tooltip("BounceModel: the library's bounce sets velocity and spin after a contact. Keep: PhysX's response, spin unchanged.")]
        public SpinAtContact spinAtContact = SpinAtContact.BounceModel;

        /// <summary>Set the Rigidbody's mass to the ball's when the model is taken (at Awake, or by <see cref="Configure"/>).</summary>
        [Tooltip("Set the Rigidbody's mass to the ball's (collisions with other bodies then exchange the right momentum).")]
        public bool setMass = true;

        private Rigidbody? _body;
        private FlightModel? _model;
        private IBounceModel? _bounce;
        private Vector3d _spin;
        private Vector3d _velocityBefore;
        private bool _configurationFailed; // the inspector's settings were refused: no retry (and no exception) every physics step
        private bool _configuredInCode; // Configure gave the model: inspector edits do not replace it
        private string? _reported; // the last inspector problem reported, so that each is reported once

        /// <summary>The ball's spin, rad/s, about world axes (left-hand rule); integrated here, not by PhysX.</summary>
        public Vector3d Spin => _spin;

        /// <summary>The flight model (from the inspector at the first use, or given to <see cref="Configure"/>).</summary>
        public FlightModel Model
        {
            get
            {
                EnsureConfigured();
                return _model!;
            }
        }

        /// <summary>
        /// Uses a model and bounce built in code instead of the inspector's (and, with <see cref="setMass"/>, sets the
        /// Rigidbody's mass to the model's ball, as Awake does).
        /// </summary>
        /// <param name="model">The flight model; its gravity is the one the body feels in total.</param>
        /// <param name="bounce">The bounce model for <see cref="SpinAtContact.BounceModel"/>, or null.</param>
        /// <exception cref="ArgumentNullException">model is null.</exception>
        public void Configure(FlightModel model, IBounceModel? bounce)
        {
            Adopt(model ?? throw new ArgumentNullException(nameof(model)), bounce);
            _configuredInCode = true;
        }

        /// <summary>
        /// Unity calls this after an inspector edit (also during Play) and when the component is loaded: the settings are
        /// checked, and once the component has taken a model (at Awake) the new one replaces it from the next physics step. A
        /// refused value is reported once with <c>Debug.LogError</c>, naming the field; the previous settings stay. Nothing
        /// happens while a model given to <see cref="Configure"/> is in use.
        /// </summary>
        private void OnValidate()
        {
            if (_configuredInCode)
            {
                return;
            }

            FlightModel model;
            IBounceModel? bounce;
            try
            {
                model = settings.CreateModel(Gravity.YUp);
                bounce = settings.CreateBounce();
            }
            catch (ArgumentException e)
            {
                UnityFrame.ReportRefusal(ref _reported, this, e);
                return;
            }

            _reported = null;
            if (_model != null || _configurationFailed)
            {
                Adopt(model, bounce); // taken at Awake already (or refused there): the edit replaces it
            }
        }

        /// <summary>Sets the spin, rad/s (left-hand rule), for example after a racket hit.</summary>
        /// <param name="angularVelocity">Spin, rad/s; finite.</param>
        /// <exception cref="ArgumentException">A component is not finite; the spin is unchanged.</exception>
        public void SetSpin(Vector3d angularVelocity)
        {
            if (!angularVelocity.IsFinite)
            {
                throw new ArgumentException($"angularVelocity must be finite; got {angularVelocity}.", nameof(angularVelocity));
            }

            _spin = angularVelocity;
        }

        /// <summary>Sets the Rigidbody's velocity and the spin at once: a launch.</summary>
        /// <param name="velocity">Velocity, m/s.</param>
        /// <param name="angularVelocity">Spin, rad/s (left-hand rule).</param>
        /// <exception cref="ArgumentException">A component is not finite, or the inspector's settings are out of range (the message names
        /// the setting); nothing changes. (Bad settings at Awake disable the component; a launch once they are mended, or
        /// <see cref="Configure"/>, enables it again.)</exception>
        public void Launch(Vector3 velocity, Vector3 angularVelocity)
        {
            EnsureConfigured();
            Vector3d v = UnityFrame.ToLibrary(velocity);
            if (!v.IsFinite)
            {
                throw new ArgumentException($"velocity must be finite; got {v}.", nameof(velocity));
            }

            SetSpin(UnityFrame.ToLibrary(angularVelocity));
            SetVelocity(Body, velocity);
            _velocityBefore = v;
        }

        /// <summary>
        /// The acceleration, m/s^2, to add to a body at <paramref name="position"/> moving at
        /// <paramref name="velocity"/> with <paramref name="spin"/>: the model's total acceleration minus
        /// <paramref name="engineGravity"/>, the gravity the physics engine applies itself. (<c>FixedUpdate</c> adds this,
        /// except where its aerodynamic part would more than stop the ball in the air within one physics step: see docs/unity.md.)
        /// </summary>
        /// <param name="model">The flight model.</param>
        /// <param name="position">Position, m.</param>
        /// <param name="velocity">Velocity, m/s.</param>
        /// <param name="spin">Spin, rad/s.</param>
        /// <param name="engineGravity">What the engine adds by itself, m/s^2 (zero without useGravity).</param>
        /// <param name="spinRate">The spin's rate of change, rad/s^2 (spin decay).</param>
        public static Vector3d AddedAcceleration(FlightModel model, Vector3d position, Vector3d velocity, Vector3d spin, Vector3d engineGravity, out Vector3d spinRate)
        {
            StateDerivative d = model.Derivative(new FlightState(position, velocity, spin));
            spinRate = d.AngularAcceleration;
            return d.Acceleration - engineGravity;
        }

        // PhysX adds a dt to the velocity (semi-implicit Euler). Where the aerodynamic part would more than stop the ball in
        // the air within one step (|a_aero| dt > s = |v - wind|, i.e. s > 2m / (rho A C_D dt) for drag: for a tennis ball at
        // 50 Hz between 2,000 and 3,000 m/s, far beyond any flight speed; a light, large custom ball much sooner), the step
        // overshoots: it reverses the ball, and beyond twice that speed (about 5,350 m/s for the tennis ball) faster every step
        // until the acceleration leaves a float's range (6,000 m/s: AddForce got infinity at the 7th step, PhysX then NaN).
        // There the aerodynamic part is scaled to stop the ball in the air in the step, and to at most 1e38 m/s^2 (a float
        // reaches 3.4e38; gravity is not capped); below, it is passed as it is.
        private static Vector3d WithinOneStep(FlightModel model, Vector3d position, Vector3d velocity, Vector3d added, Vector3d engineGravity, double dt)
        {
            Vector3d aero = added + engineGravity - model.Gravity;
            Vector3d air = velocity - model.Air.WindAt(position, model.Up);
            double airSpeed = air.Length;
            double aeroLength = aero.Length;
            if (!(aeroLength * dt > airSpeed))
            {
                return added;
            }

            double limit = Math.Min(airSpeed / dt, 1e38);
            Vector3d capped = aeroLength <= double.MaxValue
                ? aero * (limit / aeroLength)
                : air.NormalizedOrZero() * -limit; // an infinite aerodynamic part: taken as drag (scaling it would give inf x 0)
            return capped + (model.Gravity - engineGravity);
        }

        // Unity's own null test (UnityEngine.Object's ==), not ??=, which sees a destroyed component as alive.
        private Rigidbody Body
        {
            get
            {
                if (_body == null)
                {
                    _body = GetComponent<Rigidbody>();
                }

                return _body;
            }
        }

        private void Awake()
        {
            try
            {
                EnsureConfigured();
            }
            catch (ArgumentException)
            {
                // Unity logs the exception once; a disabled component gets no FixedUpdate (collision messages still come, and
                // are skipped below).
                enabled = false;
                throw;
            }
        }

        private void FixedUpdate()
        {
            if (_configurationFailed)
            {
                return; // refused once, loudly (Awake); not again every physics step
            }

            EnsureConfigured();
            Rigidbody body = Body;
            Vector3d v = UnityFrame.ToLibrary(GetVelocity(body));
            Vector3d g = body.useGravity ? UnityFrame.ToLibrary(Physics.gravity) : Vector3d.Zero;
            Vector3d position = UnityFrame.ToLibrary(body.position);
            Vector3d a = AddedAcceleration(_model!, position, v, _spin, g, out Vector3d spinRate);
            double dt = Time.fixedDeltaTime;
            body.AddForce(UnityFrame.ToUnity(WithinOneStep(_model!, position, v, a, g, dt)), ForceMode.Acceleration);
            // The spin steps with the velocity, by the same semi-implicit Euler step PhysX takes. A decay whose part along the
            // spin would more than stop it in one step (at absurd speeds) stops that part instead of reversing it; the part
            // across the spin (a law that turns the axis) is kept.
            double spinLength = _spin.Length;
            Vector3d axis = _spin.NormalizedOrZero();
            double along = Vector3d.Dot(spinRate, axis);
            if (-along * dt > spinLength)
            {
                Vector3d across = spinRate - axis * along;
                _spin = across.IsFinite ? across * dt : Vector3d.Zero;
            }
            else
            {
                _spin += spinRate * dt;
            }

            _velocityBefore = v;
        }

        private void OnCollisionEnter(Collision collision)
        {
            if (spinAtContact != SpinAtContact.BounceModel || collision.contactCount == 0)
            {
                return;
            }

            if (_configurationFailed)
            {
                return;
            }

            EnsureConfigured();
            if (_bounce == null)
            {
                return;
            }

            Rigidbody? other = collision.rigidbody;
            Vector3d otherVelocity = other != null ? UnityFrame.ToLibrary(GetVelocity(other)) : Vector3d.Zero;
            Vector3d incoming = _velocityBefore - otherVelocity;
            Vector3d normal = UnityFrame.ToLibrary(collision.GetContact(0).normal);
            if (Vector3d.Dot(normal, incoming) > 0)
            {
                normal = -normal; // the bounce model wants the normal out of the surface, against the incoming ball
            }

            if (!(normal.LengthSquared > 0) || !(Vector3d.Dot(normal, incoming) < 0))
            {
                return; // grazing or separating: nothing to bounce
            }

            BounceOutcome outcome = _bounce.Bounce(_model!.Ball, normal.NormalizedOrZero(), incoming, _spin);
            SetVelocity(Body, UnityFrame.ToUnity(outcome.Velocity + otherVelocity));
            _spin = outcome.AngularVelocity;
        }

        private void EnsureConfigured()
        {
            if (_model == null)
            {
                try
                {
                    FlightModel model = settings.CreateModel(Gravity.YUp);
                    Adopt(model, settings.CreateBounce());
                }
                catch (ArgumentException)
                {
                    _configurationFailed = true;
                    throw;
                }
            }
        }

        // The one place a model is taken (the inspector's or Configure's): with setMass the Rigidbody gets the ball's mass, and
        // a component that Awake disabled for refused settings is turned on again.
        private void Adopt(FlightModel model, IBounceModel? bounce)
        {
            _model = model;
            _bounce = bounce;
            if (_configurationFailed)
            {
                _configurationFailed = false;
                enabled = true;
            }

            if (setMass)
            {
                Body.mass = (float)model.Ball.Mass;
            }
        }

        // Unity 6 renamed Rigidbody.velocity to linearVelocity (the old name is obsolete there).
        private static Vector3 GetVelocity(Rigidbody body)
        {
#if UNITY_6000_0_OR_NEWER
            return body.linearVelocity;
#else
            return body.velocity;
#endif
        }

        private static void SetVelocity(Rigidbody body, Vector3 velocity)
        {
#if UNITY_6000_0_OR_NEWER
            body.linearVelocity = velocity;
#else
            body.velocity = velocity;
#endif
        }
    }
}
