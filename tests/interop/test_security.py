"""DDS-Security the SROS2 way: `rclada security` keystores (openssl), secured
participants from ROS_SECURITY_* and --ros-args --enclave (Cyclone's dds.sec.*
properties with Debian's plugins). A secured talker/listener pair talks; an
unsecured participant (Python cyclonedds, or Ada) neither sees the data nor
can inject; a certificate without the permission to publish is refused;
tampered permissions stop the participant under Enforce with a clear
message. Everything on loopback."""
import os
import shutil
import subprocess
import time

import pytest
from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsPublication

import pubsub_support as ps
from ros_types import String_

POLICY = """<?xml version="1.0" encoding="UTF-8"?>
<policy version="0.2.0">
  <enclaves>
    <enclave path="/no_chatter">
      <profiles>
        <profile ns="/" node="talker">
          <topics publish="DENY"><topic>chatter</topic></topics>
          <topics publish="ALLOW" subscribe="ALLOW"><topic>*</topic></topics>
          <services reply="ALLOW" request="ALLOW"><service>*</service></services>
        </profile>
      </profiles>
    </enclave>
  </enclaves>
</policy>
"""


def rclada(*args, env=None, timeout=60):
    p = subprocess.run([str(ps.BIN / "rclada"), *map(str, args)], capture_output=True,
                       text=True, timeout=timeout, env=env)
    return p.returncode, p.stdout, p.stderr


@pytest.fixture(scope="module")
def keystore(tmp_path_factory):
    ks = tmp_path_factory.mktemp("sec") / "keystore"
    for args in (["create_keystore", ks], ["create_enclave", ks, "/talker"],
                 ["create_enclave", ks, "/listener"], ["create_enclave", ks, "/no_chatter"]):
        rc, out, err = rclada("security", *args)
        assert rc == 0, err
    policy = ks.parent / "policy.xml"
    policy.write_text(POLICY)
    rc, out, err = rclada("security", "create_permission", ks, "/no_chatter", policy)
    assert rc == 0, err
    return ks


def secured(keystore, strategy="Enforce", **extra):
    return dict(os.environ, ROS_SECURITY_ENABLE="true", ROS_SECURITY_STRATEGY=strategy,
                ROS_SECURITY_KEYSTORE=str(keystore), **extra)


def start(program, *args, env):
    return subprocess.Popen([str(ps.BIN / program), *map(str, args)], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def stop(proc):
    if proc.poll() is None:
        proc.kill()
    return proc.communicate()[0]


DENY = 'publish="DENY"'


def line_of(text, part):
    return text[:text.index(part)].count("\n") + 1


def column_after(text, part):
    """The column of the character after part (1-based)."""
    start = text.rindex("\n", 0, text.index(part)) + 1
    return text.index(part) + len(part) - start + 1


BAD_POLICIES = [
    # (policy text, substrings of the error) -- each names the file, line
    # and column (found by the fuzzer's policy reader: the XML encoding was
    # an internal error, the others named no line).
    ('<?xml version="1.0" encoding="UTF-0"?>\n<policy/>\n',
     ["bad.xml:1:", "Invalid encoding: UTF-0 (malformed XML)"]),
    ("", ["bad.xml:1:0: No root element specified (malformed XML)"]),
    (POLICY.replace("<policy", "<polcy").replace("</policy>", "</polcy>"),
     [f"bad.xml:{line_of(POLICY, '<policy')}:",
      "the root element is <polcy>, expected <policy>"]),
    (POLICY.replace('publish="DENY"', 'publish="MAYBE"'),
     [f"bad.xml:{line_of(POLICY, DENY)}:",
      '<topics publish="MAYBE">: expected ALLOW or DENY']),
    (POLICY.replace('<topics publish="DENY"><topic>chatter</topic></topics>',
                    '<topics publsh="DENY"></topics>'),
     [f"bad.xml:{line_of(POLICY, DENY)}:",
      "unknown attribute 'publsh' in <topics> (expected publish, subscribe or xml:base)"]),
    (POLICY.replace("<topic>chatter</topic>", "<topic> </topic>"),
     [f"bad.xml:{line_of(POLICY, '<topic>chatter')}:",
      "an empty name in the profile of node talker"]),
    # Elements and attributes SROS2's policy schema does not define were
    # ignored silently (a misspelt group gave no rule); SROS2 refuses them.
    (POLICY.replace("<topic>chatter</topic>", "<topicz>chatter</topicz>"),
     [f"bad.xml:{line_of(POLICY, '<topic>chatter')}:",
      "unknown element 'topicz' in <topics> (expected topic)"]),
    (POLICY.replace("<services ", "<servces ").replace("</services>", "</servces>"),
     [f"bad.xml:{line_of(POLICY, '<services')}:",
      "unknown element 'servces' in <profile> (expected topics, services or actions)"]),
    (POLICY.replace('node="talker"', 'node="talker" nodes="listener"'),
     [f"bad.xml:{line_of(POLICY, 'node=')}:",
      "unknown attribute 'nodes' in <profile> (expected ns, node or xml:base)"]),
    (POLICY.replace("<topic>chatter</topic>", '<topic kind="x">chatter</topic>'),
     [f"bad.xml:{line_of(POLICY, '<topic>chatter')}:",
      "unknown attribute 'kind' in <topic> (expected none)"]),
    # ... in any enclave, not only the one asked for (SROS2 validates the file).
    (POLICY.replace("<enclaves>", '<enclaves>\n<enclave path="/other"><profiles>'
                    '<profile ns="/" node="n"><actions call="ALLOW"><action>a</action>'
                    '</actions><acton/></profile></profiles></enclave>'),
     [f"bad.xml:{line_of(POLICY, '<enclaves>') + 1}:",
      "unknown element 'acton' in <profile> (expected topics, services or actions)"]),
    # What policy.xsd requires was not checked (a missing path, ns or node
    # read as "", a group without items gave no rule silently), nor the
    # version, text between elements, the modes of the other enclaves.
    (POLICY.replace(' version="0.2.0"', ""),
     [f"bad.xml:{line_of(POLICY, '<policy')}:",
      "missing attribute 'version' in <policy> (required: version)"]),
    (POLICY.replace('version="0.2.0"', 'version="0.1.0"'),
     [f"bad.xml:{line_of(POLICY, '<policy')}:",
      '<policy version="0.1.0">: expected version 0.2.0']),
    (POLICY.replace(' path="/no_chatter"', ""),
     [f"bad.xml:{line_of(POLICY, '<enclave ')}:",
      "missing attribute 'path' in <enclave> (required: path)"]),
    (POLICY.replace(' node="talker"', ""),
     [f"bad.xml:{line_of(POLICY, '<profile ')}:",
      "missing attribute 'node' in <profile> (required: ns and node)"]),
    (POLICY.replace("<enclaves>", '<enclaves>\n<enclave path="/other"/>'),
     [f"bad.xml:{line_of(POLICY, '<enclaves>') + 1}:",
      "missing element <profiles> in <enclave> (required: one or more)"]),
    ('<?xml version="1.0"?>\n<policy version="0.2.0">\n<enclaves>\n</enclaves></policy>\n',
     ["bad.xml:3:", "missing element <enclave> in <enclaves> (required: one or more)"]),
    ('<?xml version="1.0"?>\n<policy version="0.2.0"/>\n',
     ["bad.xml:2:", "missing element <enclaves> in <policy> (required: one)"]),
    (POLICY.replace("</enclaves>", "</enclaves>\n<enclaves/>"),
     [f"bad.xml:{line_of(POLICY, '</enclaves>') + 1}:",
      "a second <enclaves> in <policy> (allowed: one)"]),
    (POLICY.replace("<topic>chatter</topic>", ""),
     [f"bad.xml:{line_of(POLICY, DENY)}:",
      "missing element <topic> in <topics> (required: one or more)"]),
    (POLICY.replace("<profiles>", "<profiles>\n  allow everything"),
     [f"bad.xml:{line_of(POLICY, '<profiles>') + 1}:",
      "text 'allow everything' in <profiles> (only elements are allowed there)"]),
    # Located at the text's first character, in a CDATA section or after an
    # entity reference too (was: the column after the section, or one early).
    (POLICY.replace("<profiles>", "<profiles>\n<![CDATA[allow]]>"),
     [f"bad.xml:{line_of(POLICY, '<profiles>') + 1}:10: text 'allow' in <profiles>"]),
    (POLICY.replace("<profiles>", "<profiles>\t&amp;"),
     [f"bad.xml:{line_of(POLICY, '<profiles>')}:{column_after(POLICY, '<profiles>') + 1}: "
      "text '&' in <profiles>"]),
    (POLICY.replace('<topics publish="DENY">', '<topics publish="DENY">chatter'),
     [f"bad.xml:{line_of(POLICY, DENY)}:",
      "text 'chatter' in <topics> (only elements are allowed there)"]),
    (POLICY.replace("<profiles>", "<profiles><metadata/>"),
     [f"bad.xml:{line_of(POLICY, '<profile ')}:",
      "<profile> after <metadata> in <profiles> (the <metadata> comes last)"]),
    (POLICY.replace("</profiles>", "<metadata/><metadata/></profiles>"),
     [f"bad.xml:{line_of(POLICY, '</profiles>')}:",
      "a second <metadata> in <profiles> (allowed: one)"]),
    (POLICY.replace("<enclaves>", '<enclaves>\n<enclave path="/other"><profiles>'
                    '<profile ns="/" node="n"><topics publish="allow"><topic>a</topic>'
                    '</topics></profile></profiles></enclave>'),
     [f"bad.xml:{line_of(POLICY, '<enclaves>') + 1}:",
      '<topics publish="allow">: expected ALLOW or DENY']),
    (POLICY.replace("<topic>chatter</topic>", "<topic>\n\t\n</topic>"),
     [f"bad.xml:{line_of(POLICY, '<topic>chatter')}:",
      "an empty name in the profile of node talker"]),
    # Names SROS2 joins into topic names: a namespace without its leading
    # '/' gave "rt/obots/chatter" (first letter cut), a space a topic no
    # participant can have.
    (POLICY.replace('ns="/"', 'ns="robots"'),
     [f"bad.xml:{line_of(POLICY, '<profile ')}:",
      "in <profile>: namespace \"robots\": must start with '/'"]),
    (POLICY.replace('node="talker"', 'node="tal ker"'),
     [f"bad.xml:{line_of(POLICY, '<profile ')}:",
      "in <profile>: node name \"tal ker\": invalid character ' ' at position 4"]),
    (POLICY.replace("<topic>chatter</topic>", "<topic>chat ter</topic>"),
     [f"bad.xml:{line_of(POLICY, '<topic>chatter')}:",
      "<topic> 'chat ter': invalid character ' ' at position 5"]),
    (POLICY.replace("<service>*</service>", "<service>a~b</service>"),
     [f"bad.xml:{line_of(POLICY, '<service>')}:",
      "<service> 'a~b': invalid character '~' at position 2"]),
    # ... in any enclave (was: only in the one asked for).
    (POLICY.replace("<enclaves>", '<enclaves>\n<enclave path="/other"><profiles>'
                    '<profile ns="/" node="other"><topics publish="ALLOW"><topic/>'
                    '</topics></profile></profiles></enclave>'),
     [f"bad.xml:{line_of(POLICY, '<enclaves>') + 1}:",
      "an empty name in the profile of node other"]),
    # 100,000 nested elements took minutes (the XML reader is quadratic in
    # the depth); a 4 MB element name overflowed its stack (internal error).
    (POLICY.replace("<profiles>", "<profiles>" + "<a>" * 100000 + "</a>" * 100000),
     [f"bad.xml:{line_of(POLICY, '<profiles>')}:", "elements nested deeper than 100"]),
    (POLICY.replace("<profiles>", "<profiles><" + "x" * 4000000 + "/>"),
     ["bad.xml: 4000", "bytes: a policy file may not exceed 1048576 bytes"]),
]


@pytest.mark.parametrize("text,expected", BAD_POLICIES, ids=range(len(BAD_POLICIES)))
def test_bad_policies_name_file_line_and_column(keystore, tmp_path, text, expected):
    bad = tmp_path / "bad.xml"
    bad.write_text(text)
    rc, out, err = rclada("security", "create_permission", keystore, "/no_chatter", bad)
    assert rc == 1, err
    for e in expected:
        assert e in err, err
    assert "internal error" not in err, err


def test_policy_with_every_schema_construct_is_accepted(keystore, tmp_path):
    # What SROS2's policy schema allows besides rules: profiles type, a
    # <metadata> of any content, xml:base, namespace declarations.
    text = (POLICY.replace("<policy ", '<policy xmlns:xi="http://www.w3.org/2001/XInclude" ')
            .replace("<profiles>", '<profiles type="ros">')
            .replace('node="talker"', 'node="talker" xml:base="."')
            .replace('ns="/"', 'ns="/robots/r1/"')
            .replace("<topic>*</topic>", "<topic>*</topic><topic>[a-z]*</topic><topic>~</topic>"
                     "<topic>~/state</topic><topic>/rq/*</topic>")
            .replace("</profile>\n", '<actions call="ALLOW" xml:base="."><action>fib</action>'
                     '</actions><!-- a comment -->\n'
                     '<topics subscribe="ALLOW"><topic><![CDATA[cdata_topic]]></topic>'
                     "<topic>\n\t   spaced_topic\n</topic></topics></profile>\n"
                     '<metadata note="any attribute">any text<anything x="1"><topicz/>'
                     '</anything>\n<profile ns="/" node="talker"><topics subscribe="ALLOW">'
                     "<topic>in_metadata</topic></topics></profile></metadata>\n"))
    good = tmp_path / "good.xml"
    good.write_text(text)
    copy = tmp_path / "keystore"  # the other tests' keystore stays as it is
    shutil.copytree(keystore, copy, symlinks=True)
    rc, out, err = rclada("security", "create_permission", copy, "/no_chatter", good)
    assert rc == 0, err + text
    permissions = (copy / "enclaves" / "no_chatter" / "permissions.xml").read_text()
    assert "rq/robots/r1/fib/_action/send_goalRequest" in permissions, permissions
    assert "<topic>rt/robots/r1/cdata_topic</topic>" in permissions, permissions
    assert "<topic>rt/robots/r1/spaced_topic</topic>" in permissions, permissions
    assert "<topic>rt/robots/r1/talker/state</topic>" in permissions, permissions
    assert "<topic>rt/robots/r1/[a-z]*</topic>" in permissions, permissions
    # <metadata> is of any content: a <profile> in it grants nothing.
    assert "in_metadata" not in permissions, permissions


def test_keystore_layout_and_list(keystore):
    rc, out, err = rclada("security", "list_enclaves", keystore)
    assert rc == 0, err
    assert out.split() == ["/listener", "/no_chatter", "/talker"]
    enclave = keystore / "enclaves" / "talker"
    for name in ("cert.pem", "key.pem", "permissions.xml", "permissions.p7s",
                 "identity_ca.cert.pem", "permissions_ca.cert.pem", "governance.p7s"):
        assert (enclave / name).exists(), name
    assert os.path.islink(enclave / "governance.p7s")
    # Independent check with openssl: the signature verifies against the CA,
    # the certificate names the enclave.
    verify = subprocess.run(
        ["openssl", "smime", "-verify", "-in", enclave / "permissions.p7s",
         "-CAfile", keystore / "public" / "permissions_ca.cert.pem"], capture_output=True,
        text=True)
    assert verify.returncode == 0, verify.stderr
    assert "<subject_name>CN=/talker</subject_name>" in verify.stdout
    subject = subprocess.run(["openssl", "x509", "-in", enclave / "cert.pem", "-noout",
                              "-subject"], capture_output=True, text=True).stdout
    assert "/talker" in subject
    permissions = (keystore / "enclaves" / "no_chatter" / "permissions.xml").read_text()
    deny = permissions.index("<deny_rule>")
    assert permissions.index("<topic>rt/chatter</topic>", deny) < permissions.index("</deny_rule>")
    assert "<topic>rq/*Request</topic>" in permissions


def test_secured_pair_works_and_outsiders_get_nothing(keystore):
    listener = start("listener", "--ros-args", "--enclave", "/listener", env=secured(keystore))
    talker = start("talker", "--ros-args", "--enclave", "/talker", env=secured(keystore))
    dp = ps.participant()
    injector = ps.participant()
    try:
        # Unsecured participants on the same domain: no data, no topic names
        # (discovery is encrypted), and what they write reaches no one.
        rd = ps.reader(dp, "rt/chatter", String_)
        wr = ps.writer(injector, "rt/chatter", String_)
        pubs = BuiltinDataReader(dp, BuiltinTopicDcpsPublication)
        deadline = time.monotonic() + 6
        while time.monotonic() < deadline:
            wr.write(String_(data="INJECTED"))
            time.sleep(0.2)
        heard = [s.data for s in ps.take(rd)]
        assert heard and set(heard) == {"INJECTED"}, heard  # only the other outsider
        outsiders = {dp.guid, injector.guid}
        names = {p.topic_name for p in pubs.take(N=1000) if p.participant_key not in outsiders}
        assert "rt/chatter" not in names, names
        # The injector's writer matched the outsider's reader only.
        assert wr.get_publication_matched_status().total_count == 1
        # An unsecured Ada participant does not hear the talker either.
        echo = subprocess.run(["timeout", "4", str(ps.BIN / "rclada"), "topic", "echo",
                               "/chatter", "std_msgs/msg/String", "--once"],
                              capture_output=True, text=True)
        assert echo.returncode == 124 and "data:" not in echo.stdout, echo.stdout
    finally:
        talker_out = stop(talker)
        listener_out = stop(listener)
    assert "Got chatter: 'Hello World" in listener_out, listener_out + talker_out
    assert "INJECTED" not in listener_out


def test_enclave_without_permission_is_refused(keystore):
    talker = start("talker", "--ros-args", "--enclave", "/no_chatter", env=secured(keystore))
    try:
        talker.wait(timeout=30)
    finally:
        out = stop(talker)
    assert talker.returncode != 0, out
    assert "rt/chatter" in out and "security" in out.lower(), out


def test_tampered_permissions_stop_the_participant(keystore, tmp_path):
    copy = tmp_path / "keystore"
    shutil.copytree(keystore, copy, symlinks=True)
    signed = copy / "enclaves" / "talker" / "permissions.p7s"
    text = signed.read_text()
    assert "<default>DENY</default>" in text
    signed.write_text(text.replace("<default>DENY</default>", "<default>ALLOW</default>"))
    talker = start("talker", "--ros-args", "--enclave", "/talker", env=secured(copy))
    try:
        talker.wait(timeout=30)
    finally:
        out = stop(talker)
    assert talker.returncode != 0, out
    assert "refused the enclave's files" in out, out
    assert "permissions" in out.lower()


def test_missing_enclave_enforce_and_permissive(keystore):
    talker = start("talker", "--ros-args", "--enclave", "/nobody", env=secured(keystore))
    try:
        talker.wait(timeout=30)
    finally:
        out = stop(talker)
    assert talker.returncode != 0
    assert "SECURITY ERROR" in out and "/nobody" in out, out
    # Permissive: a warning, then unsecured (a plain participant hears it).
    dp = ps.participant()
    rd = ps.reader(dp, "rt/chatter", String_)
    talker = start("talker", "--ros-args", "--enclave", "/nobody",
                   env=secured(keystore, strategy="Permissive"))
    try:
        got = ps.take_until(rd, 1, timeout=15)
    finally:
        out = stop(talker)
    assert got and got[0].data.startswith("Hello World"), out
    assert "running unsecured" in out, out
