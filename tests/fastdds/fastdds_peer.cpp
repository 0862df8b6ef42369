// A Fast DDS 2.9 participant that behaves on the wire as an rmw_fastrtps_cpp
// (ROS 2 Humble) node: the test peer nobody on the project wrote the DDS of.
//
//   participant USER_DATA "enclave=/;", a ros_discovery_info writer (reliable,
//   transient local, keep last 1, 24-byte gids) announcing the node and its
//   endpoints, "rt/" topic names, "pkg::msg::dds_::Type_" type names, the ROS 2
//   default QoS (reliable, volatile, keep last 10) or sensor data (best effort,
//   keep last 5), asynchronous publishing; services the rmw_fastrtps way
//   ("rq/<name>Request" / "rr/<name>Reply", no header in the payload, replies
//   correlated by the related-sample-identity inline QoS).
//
// Payloads are raw CDR (with the 4-byte encapsulation header): the test
// builds and checks them; the peer moves bytes.
//
//   fastdds_peer --node talker --pub /chatter std_msgs::msg::dds_::String_ hi.cdr
//                --count 5 --duration 10
//   fastdds_peer --node listener --sub /chatter std_msgs::msg::dds_::String_
//                --exit-after 3 --duration 10
//
// Output lines (stdout, one event per line):
//   ready
//   sample <topic> <length> <fnv1a64 hex> <payload hex, only up to 65536 bytes>
//   node <namespace> <name>           (from a ros_discovery_info sample)
//   writer <dds topic> <type>          (discovered through DDS discovery)
//   reader <dds topic> <type>
//   request sent                       (--call; repeated every 2 s until a reply)
//   reply <sum>                        (--call)
//   served <a> <b>                     (--serve)
// The loopback profile is mandatory: FASTRTPS_DEFAULT_PROFILES_FILE must name
// share/fastdds-localhost.xml (or another file); without it the peer refuses
// to start rather than multicast on the machine's network.

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastrtps/rtps/common/WriteParams.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::SerializedPayload_t;
using eprosima::fastrtps::rtps::InstanceHandle_t;
using eprosima::fastrtps::rtps::GUID_t;
using eprosima::fastrtps::rtps::WriteParams;
using Bytes = std::vector<uint8_t>;

namespace {

std::mutex out_mutex;

void say(const std::string& line)
{
    std::lock_guard<std::mutex> lock(out_mutex);
    std::cout << line << std::endl;
}

[[noreturn]] void fail(const std::string& why)
{
    std::cerr << "fastdds_peer: " << why << std::endl;
    std::exit(2);
}

std::string hex(const uint8_t* data, size_t size)
{
    static const char digits[] = "0123456789abcdef";
    std::string text(2 * size, '0');
    for (size_t i = 0; i < size; ++i) {
        text[2 * i] = digits[data[i] >> 4];
        text[2 * i + 1] = digits[data[i] & 15];
    }
    return text;
}

uint64_t fnv1a64(const uint8_t* data, size_t size)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t i = 0; i < size; ++i) {
        h ^= data[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}

// A sample is its CDR bytes, encapsulation header included.
struct RawSample {
    Bytes bytes;
};

// A topic type that moves CDR bytes unchanged under a ROS 2 type name.
class RawType : public TopicDataType {
public:
    explicit RawType(const std::string& name)
    {
        setName(name.c_str());
        m_typeSize = 64;  // grows per sample (PREALLOCATED_WITH_REALLOC pools)
        m_isGetKeyDefined = false;
        auto_fill_type_object(false);
        auto_fill_type_information(false);
    }

    bool serialize(void* data, SerializedPayload_t* payload) override
    {
        const Bytes& bytes = static_cast<RawSample*>(data)->bytes;
        if (bytes.size() < 4 || payload->max_size < bytes.size()) {
            return false;
        }
        std::memcpy(payload->data, bytes.data(), bytes.size());
        payload->length = static_cast<uint32_t>(bytes.size());
        payload->encapsulation = bytes[1] == 1 ? CDR_LE : CDR_BE;
        return true;
    }

    bool deserialize(SerializedPayload_t* payload, void* data) override
    {
        static_cast<RawSample*>(data)->bytes.assign(payload->data, payload->data + payload->length);
        return true;
    }

    std::function<uint32_t()> getSerializedSizeProvider(void* data) override
    {
        const size_t size = static_cast<RawSample*>(data)->bytes.size();
        return [size]() { return static_cast<uint32_t>(size); };
    }

    void* createData() override { return new RawSample(); }
    void deleteData(void* data) override { delete static_cast<RawSample*>(data); }
    bool getKey(void*, InstanceHandle_t*, bool) override { return false; }
};

// Little-endian CDR writer for the ros_discovery_info and service samples.
class Cdr {
public:
    Cdr() : bytes_{0, 1, 0, 0} {}
    void align(size_t n)
    {
        while ((bytes_.size() - 4) % n != 0) bytes_.push_back(0);
    }
    void u32(uint32_t v)
    {
        align(4);
        for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<uint8_t>(v >> (8 * i)));
    }
    void i64(int64_t v)
    {
        align(8);
        for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<uint8_t>(uint64_t(v) >> (8 * i)));
    }
    void raw(const uint8_t* data, size_t n) { bytes_.insert(bytes_.end(), data, data + n); }
    void str(const std::string& s)
    {
        u32(static_cast<uint32_t>(s.size() + 1));
        raw(reinterpret_cast<const uint8_t*>(s.c_str()), s.size() + 1);
    }
    Bytes finish()
    {
        while (bytes_.size() % 4 != 0) bytes_.push_back(0);
        return bytes_;
    }

private:
    Bytes bytes_;
};

// Little-endian / big-endian aware CDR reader; throws on a short buffer.
class CdrIn {
public:
    explicit CdrIn(const Bytes& b) : b_(b), pos_(4), swap_(b.size() < 4 || b[1] != 1)
    {
        if (b.size() < 4) throw std::runtime_error("short sample");
    }
    void align(size_t n)
    {
        while ((pos_ - 4) % n != 0) ++pos_;
    }
    uint32_t u32()
    {
        align(4);
        need(4);
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) {
            const uint32_t byte = b_[pos_ + (swap_ ? 3 - i : i)];
            v |= byte << (8 * i);
        }
        pos_ += 4;
        return v;
    }
    int64_t i64()
    {
        align(8);
        need(8);
        uint64_t v = 0;
        for (int i = 0; i < 8; ++i) {
            const uint64_t byte = b_[pos_ + (swap_ ? 7 - i : i)];
            v |= byte << (8 * i);
        }
        pos_ += 8;
        return static_cast<int64_t>(v);
    }
    std::string str()
    {
        const uint32_t n = u32();
        need(n);
        std::string s(reinterpret_cast<const char*>(&b_[pos_]), n > 0 ? n - 1 : 0);
        pos_ += n;
        return s;
    }
    void skip(size_t n)
    {
        need(n);
        pos_ += n;
    }

private:
    void need(size_t n)
    {
        if (pos_ + n > b_.size()) throw std::runtime_error("short sample");
    }
    const Bytes& b_;
    size_t pos_;
    bool swap_;
};

Bytes gid_of(const GUID_t& guid)
{
    Bytes gid(24, 0);
    std::memcpy(gid.data(), guid.guidPrefix.value, 12);
    std::memcpy(gid.data() + 12, guid.entityId.value, 4);
    return gid;
}

std::string ros_to_dds(const std::string& prefix, const std::string& name, const std::string& suffix)
{
    // "/chatter" -> "rt/chatter"; relative names are taken as absolute.
    return prefix + (name.size() > 0 && name[0] == '/' ? name.substr(1) : name) + suffix;
}

Bytes read_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot read " + path);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Options {
    std::string node = "fastdds_peer";
    std::string ns = "/";
    struct Pub { std::string topic, type, file; };
    struct Sub { std::string topic, type; };
    std::vector<Pub> pubs;
    std::vector<Sub> subs;
    bool sensor = false;
    int count = -1;  // samples per publisher, -1: until the end
    double period = 0.1;
    double duration = 10.0;
    int exit_after = -1;  // received samples that end the run
    std::string serve;   // AddTwoInts service name
    std::string call;    // AddTwoInts service name
    int64_t a = 0, b = 0;
};

Options parse(int argc, char** argv)
{
    Options o;
    auto need = [&](int i, int n) {
        if (i + n >= argc) fail(std::string(argv[i]) + " needs " + std::to_string(n) + " value(s)");
    };
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--node") { need(i, 1); o.node = argv[++i]; }
        else if (a == "--namespace") { need(i, 1); o.ns = argv[++i]; }
        else if (a == "--pub") { need(i, 3); o.pubs.push_back({argv[i + 1], argv[i + 2], argv[i + 3]}); i += 3; }
        else if (a == "--sub") { need(i, 2); o.subs.push_back({argv[i + 1], argv[i + 2]}); i += 2; }
        else if (a == "--sensor") { o.sensor = true; }
        else if (a == "--count") { need(i, 1); o.count = std::atoi(argv[++i]); }
        else if (a == "--period") { need(i, 1); o.period = std::atof(argv[++i]); }
        else if (a == "--duration") { need(i, 1); o.duration = std::atof(argv[++i]); }
        else if (a == "--exit-after") { need(i, 1); o.exit_after = std::atoi(argv[++i]); }
        else if (a == "--serve") { need(i, 1); o.serve = argv[++i]; }
        else if (a == "--call") {
            need(i, 3);
            o.call = argv[i + 1];
            o.a = std::atoll(argv[i + 2]);
            o.b = std::atoll(argv[i + 3]);
            i += 3;
        }
        else fail("unknown argument " + a);
    }
    return o;
}

std::atomic<int> received{0};

class SampleListener : public DataReaderListener {
public:
    explicit SampleListener(std::string topic) : topic_(std::move(topic)) {}
    void on_data_available(DataReader* reader) override
    {
        RawSample sample;
        SampleInfo info;
        while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            const Bytes& b = sample.bytes;
            std::ostringstream line;
            line << "sample " << topic_ << " " << b.size() << " " << std::hex << fnv1a64(b.data(), b.size());
            if (b.size() <= 65536) line << " " << hex(b.data(), b.size());
            say(line.str());
            ++received;
        }
    }

private:
    std::string topic_;
};

// Prints every node of every ros_discovery_info sample (other participants').
class DiscoveryInfoListener : public DataReaderListener {
public:
    void on_data_available(DataReader* reader) override
    {
        RawSample sample;
        SampleInfo info;
        while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            try {
                CdrIn in(sample.bytes);
                in.skip(24);
                const uint32_t nodes = in.u32();
                for (uint32_t n = 0; n < nodes && n < 10000; ++n) {
                    const std::string ns = in.str();
                    const std::string name = in.str();
                    for (int seq = 0; seq < 2; ++seq) {
                        const uint32_t gids = in.u32();
                        if (gids > 100000) throw std::runtime_error("gid count");
                        in.skip(24 * size_t(gids));
                    }
                    say("node " + ns + " " + name);
                }
            } catch (const std::exception& e) {
                say(std::string("bad ros_discovery_info sample: ") + e.what());
            }
        }
    }
};

class GraphListener : public DomainParticipantListener {
public:
    void on_publisher_discovery(DomainParticipant*,
                                eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override
    {
        if (info.status == eprosima::fastrtps::rtps::WriterDiscoveryInfo::DISCOVERED_WRITER) {
            say("writer " + std::string(info.info.topicName()) + " " + std::string(info.info.typeName()));
        }
    }
    void on_subscriber_discovery(DomainParticipant*,
                                 eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override
    {
        if (info.status == eprosima::fastrtps::rtps::ReaderDiscoveryInfo::DISCOVERED_READER) {
            say("reader " + std::string(info.info.topicName()) + " " + std::string(info.info.typeName()));
        }
    }
};

const char* const add_two_ints_request = "example_interfaces::srv::dds_::AddTwoInts_Request_";
const char* const add_two_ints_response = "example_interfaces::srv::dds_::AddTwoInts_Response_";

}  // namespace

int main(int argc, char** argv)
{
    const Options opt = parse(argc, argv);
    const char* profiles = std::getenv("FASTRTPS_DEFAULT_PROFILES_FILE");
    if (profiles == nullptr || *profiles == '\0') {
        fail("FASTRTPS_DEFAULT_PROFILES_FILE is not set: refusing to start without the "
             "loopback-only profile (share/fastdds-localhost.xml)");
    }
    const char* domain_text = std::getenv("ROS_DOMAIN_ID");
    const int domain = domain_text != nullptr ? std::atoi(domain_text) : 0;

    auto* factory = DomainParticipantFactory::get_instance();
    // Before the default QoS is taken, or the profile is silently ignored.
    if (factory->load_profiles() != ReturnCode_t::RETCODE_OK) {
        fail(std::string("cannot load the profiles of ") + profiles);
    }
    DomainParticipantQos pqos = factory->get_default_participant_qos();
    const std::string enclave = "enclave=/;";
    pqos.user_data().data_vec(Bytes(enclave.begin(), enclave.end()));
    pqos.name(opt.node.c_str());
    GraphListener graph;
    DomainParticipant* participant = factory->create_participant(
        domain, pqos, &graph, StatusMask::none());
    if (participant == nullptr) fail("cannot create the participant");
    Publisher* publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
    Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);

    std::map<std::string, Topic*> topics;
    auto topic_for = [&](const std::string& name, const std::string& type) {
        auto found = topics.find(name);
        if (found != topics.end()) return found->second;
        TypeSupport support(new RawType(type));
        if (participant->find_type(type) == nullptr) support.register_type(participant);
        Topic* t = participant->create_topic(name, type, TOPIC_QOS_DEFAULT);
        if (t == nullptr) fail("cannot create topic " + name);
        topics[name] = t;
        return t;
    };
    auto endpoint_qos = [&](auto qos) {
        qos.history().kind = KEEP_LAST_HISTORY_QOS;
        qos.history().depth = opt.sensor ? 5 : 10;
        qos.reliability().kind = opt.sensor ? BEST_EFFORT_RELIABILITY_QOS : RELIABLE_RELIABILITY_QOS;
        qos.durability().kind = VOLATILE_DURABILITY_QOS;
        qos.endpoint().history_memory_policy =
            eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
        return qos;
    };
    auto writer_qos = [&]() {
        DataWriterQos q = endpoint_qos(publisher->get_default_datawriter_qos());
        q.publish_mode().kind = ASYNCHRONOUS_PUBLISH_MODE;
        q.data_sharing().off();
        return q;
    };
    auto reader_qos = [&]() {
        DataReaderQos q = endpoint_qos(subscriber->get_default_datareader_qos());
        q.data_sharing().off();
        return q;
    };

    std::vector<GUID_t> reader_gids, writer_gids;
    std::vector<std::unique_ptr<SampleListener>> listeners;
    std::vector<std::pair<DataWriter*, Bytes>> writers;

    for (const auto& s : opt.subs) {
        listeners.push_back(std::make_unique<SampleListener>(s.topic));
        DataReader* r = subscriber->create_datareader(
            topic_for(ros_to_dds("rt/", s.topic, ""), s.type), reader_qos(), listeners.back().get());
        if (r == nullptr) fail("cannot create a reader on " + s.topic);
        reader_gids.push_back(r->guid());
    }
    for (const auto& p : opt.pubs) {
        DataWriter* w = publisher->create_datawriter(
            topic_for(ros_to_dds("rt/", p.topic, ""), p.type), writer_qos());
        if (w == nullptr) fail("cannot create a writer on " + p.topic);
        writers.emplace_back(w, read_file(p.file));
        writer_gids.push_back(w->guid());
    }

    // Services, rmw_fastrtps style.
    DataWriter* request_writer = nullptr;
    DataReader* reply_reader = nullptr;
    DataReader* request_reader = nullptr;
    DataWriter* reply_writer = nullptr;
    const std::string service = !opt.serve.empty() ? opt.serve : opt.call;
    if (!service.empty()) {
        Topic* rq = topic_for(ros_to_dds("rq/", service, "Request"), add_two_ints_request);
        Topic* rr = topic_for(ros_to_dds("rr/", service, "Reply"), add_two_ints_response);
        if (!opt.serve.empty()) {
            request_reader = subscriber->create_datareader(rq, reader_qos());
            reply_writer = publisher->create_datawriter(rr, writer_qos());
            reader_gids.push_back(request_reader->guid());
            writer_gids.push_back(reply_writer->guid());
        } else {
            request_writer = publisher->create_datawriter(rq, writer_qos());
            reply_reader = subscriber->create_datareader(rr, reader_qos());
            writer_gids.push_back(request_writer->guid());
            reader_gids.push_back(reply_reader->guid());
        }
    }

    // The graph: ros_discovery_info, as rmw_dds_common publishes it.
    Topic* info_topic = topic_for("ros_discovery_info",
                                  "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_");
    DataWriterQos info_wqos = writer_qos();
    info_wqos.history().depth = 1;
    info_wqos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    info_wqos.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
    DataWriter* info_writer = publisher->create_datawriter(info_topic, info_wqos);
    DataReaderQos info_rqos = reader_qos();
    info_rqos.history().kind = KEEP_ALL_HISTORY_QOS;
    info_rqos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    info_rqos.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
    DiscoveryInfoListener info_listener;
    DataReader* info_reader = subscriber->create_datareader(info_topic, info_rqos, &info_listener);
    if (info_writer == nullptr || info_reader == nullptr) fail("cannot create ros_discovery_info endpoints");
    {
        Cdr cdr;
        const Bytes gid = gid_of(participant->guid());
        cdr.raw(gid.data(), gid.size());
        cdr.u32(1);
        cdr.str(opt.ns);
        cdr.str(opt.node);
        for (const auto* gids : {&reader_gids, &writer_gids}) {
            cdr.u32(static_cast<uint32_t>(gids->size()));
            for (const auto& g : *gids) {
                const Bytes b = gid_of(g);
                cdr.raw(b.data(), b.size());
            }
        }
        RawSample info{cdr.finish()};
        info_writer->write(&info);
    }
    say("ready");

    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    std::vector<int> sent(writers.size(), 0);
    // The call goes out once both endpoints have been matched for a second
    // (the server's reader may match this writer later than this writer
    // matched it; a volatile request sent before is lost), and again every
    // 2 s until a reply comes.
    double matched_since = -1.0;
    double last_call = -1.0;
    while (elapsed() < opt.duration) {
        for (size_t i = 0; i < writers.size(); ++i) {
            PublicationMatchedStatus status;
            writers[i].first->get_publication_matched_status(status);
            if (status.current_count > 0 && (opt.count < 0 || sent[i] < opt.count)) {
                RawSample s{writers[i].second};
                if (writers[i].first->write(&s)) ++sent[i];
            }
        }
        if (request_reader != nullptr) {
            RawSample request;
            SampleInfo info;
            while (request_reader->take_next_sample(&request, &info) == ReturnCode_t::RETCODE_OK) {
                if (!info.valid_data) continue;
                try {
                    CdrIn in(request.bytes);  // no header: the body right away
                    const int64_t a = in.i64();
                    const int64_t b = in.i64();
                    Cdr reply;
                    reply.i64(a + b);
                    RawSample out{reply.finish()};
                    WriteParams params;
                    params.related_sample_identity(info.sample_identity);
                    reply_writer->write(&out, params);
                    say("served " + std::to_string(a) + " " + std::to_string(b));
                } catch (const std::exception& e) {
                    say(std::string("bad request: ") + e.what());
                }
            }
        }
        if (request_writer != nullptr) {
            PublicationMatchedStatus w_status;
            SubscriptionMatchedStatus r_status;
            request_writer->get_publication_matched_status(w_status);
            reply_reader->get_subscription_matched_status(r_status);
            static eprosima::fastrtps::rtps::SampleIdentity sent_id;
            const bool matched = w_status.current_count > 0 && r_status.current_count > 0;
            if (!matched) {
                matched_since = -1.0;
            } else if (matched_since < 0.0) {
                matched_since = elapsed();
            }
            if (matched && received == 0 && elapsed() - matched_since >= 1.0
                && (last_call < 0.0 || elapsed() - last_call >= 2.0)) {
                Cdr body;
                body.i64(opt.a);
                body.i64(opt.b);
                RawSample request{body.finish()};
                WriteParams params;
                params.related_sample_identity().writer_guid(reply_reader->guid());
                if (request_writer->write(&request, params)) {
                    sent_id = params.sample_identity();
                    last_call = elapsed();
                    say("request sent");
                }
            }
            RawSample reply;
            SampleInfo info;
            while (reply_reader->take_next_sample(&reply, &info) == ReturnCode_t::RETCODE_OK) {
                if (!info.valid_data) continue;
                if (info.related_sample_identity != sent_id) {
                    say("reply for another request (" + std::to_string(reply.bytes.size()) + " bytes)");
                    continue;
                }
                try {
                    CdrIn in(reply.bytes);
                    say("reply " + std::to_string(in.i64()));
                    ++received;
                } catch (const std::exception& e) {
                    say(std::string("bad reply: ") + e.what());
                }
            }
        }
        if (opt.exit_after > 0 && received >= opt.exit_after) break;
        if (opt.count >= 0 && !writers.empty() && opt.exit_after < 0 && opt.subs.empty()) {
            bool done = true;
            for (int n : sent) done = done && n >= opt.count;
            if (done) {
                std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let them arrive
                break;
            }
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(opt.period));
    }
    participant->delete_contained_entities();
    factory->delete_participant(participant);
    return 0;
}
